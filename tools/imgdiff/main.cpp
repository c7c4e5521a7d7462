// imgdiff: compares two renders. Prints RMSE, PSNR, SSIM, the 99th-percentile error and the mean
// ꟻLIP (engine/io/flip.h, at --ppd pixels per degree) on the display image, and for EXR the RMSE
// of the linear HDR values; optionally writes an error heatmap PNG. EXR renders are displayed
// through the project's display transform (ACES tone map + sRGB); PNGs are display images already
// (8-bit sRGB), so two PNGs compare as they are.
//   imgdiff A.exr B.exr [--heatmap OUT.png] [--scale S] [--ppd P]
//   imgdiff A.png B.png [--heatmap OUT.png] [--scale S] [--ppd P]
// Exit codes: 0 compared; 2 bad arguments or unreadable/mismatched images.

#include "engine/io/exr.h"
#include "engine/io/flip.h"
#include "engine/io/io_error.h"
#include "engine/io/metrics.h"
#include "engine/io/png.h"
#include "engine/io/tone_map.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

int main(int argc, char** argv) {
    std::string a, b, heatmap;
    float scale = 4.0f;
    double ppd = eng::io::kFlipDefaultPixelsPerDegree;
    for (int i = 1; i < argc; ++i) {
        std::string arg = argv[i];
        if (arg == "--heatmap" && i + 1 < argc)
            heatmap = argv[++i];
        else if (arg == "--scale" && i + 1 < argc) {
            try {
                scale = std::stof(argv[++i]);
            } catch (const std::exception&) {
                scale = -1.0f;
            }
            if (!(scale > 0.0f) || !std::isfinite(scale)) {
                std::fprintf(stderr, "imgdiff: --scale must be a positive number\n");
                return 2;
            }
        } else if (arg == "--ppd" && i + 1 < argc) {
            try {
                ppd = std::stod(argv[++i]);
            } catch (const std::exception&) {
                ppd = -1.0;
            }
            if (!(ppd > 0.0) || !std::isfinite(ppd)) {
                std::fprintf(stderr, "imgdiff: --ppd (pixels per degree of the viewer) must be a positive "
                                     "number; the paper's default is 67.02\n");
                return 2;
            }
        } else if (arg == "--help" || arg == "-h") {
            std::printf(
                "usage: imgdiff A.exr B.exr | A.png B.png [--heatmap OUT.png] [--scale S] [--ppd P]\n");
            return 0;
        } else if (a.empty())
            a = arg;
        else if (b.empty())
            b = arg;
        else {
            std::fprintf(
                stderr,
                "imgdiff: unexpected argument '%s' (usage: imgdiff A.exr B.exr [--heatmap OUT.png])\n",
                arg.c_str());
            return 2;
        }
    }
    if (b.empty()) {
        std::fprintf(stderr, "usage: imgdiff A.exr B.exr [--heatmap OUT.png] [--scale S]\n");
        return 2;
    }
    try {
        const auto isPng = [](const std::string& f) {
            return std::filesystem::path(f).extension() == ".png";
        };
        if (isPng(a) != isPng(b)) {
            std::fprintf(stderr,
                         "imgdiff: compare two EXR renders or two PNG display images, not one of each\n");
            return 2;
        }
        eng::io::ImageF ha, hb, da, db;
        if (isPng(a)) {
            da = eng::io::dequantized(eng::io::readPng(a));
            db = eng::io::dequantized(eng::io::readPng(b));
        } else {
            ha = eng::io::readExr(a);
            hb = eng::io::readExr(b);
            da = eng::io::toneMapped(ha);
            db = eng::io::toneMapped(hb);
        }
        std::printf("display RMSE %.6f  PSNR %.2f dB  SSIM %.5f  p99 %.5f  FLIP %.6f", eng::io::rmse(da, db),
                    eng::io::psnr(da, db), eng::io::ssim(da, db), eng::io::percentileAbsError(da, db, 99.0),
                    eng::io::flipMean(da, db, ppd));
        if (!isPng(a)) std::printf("  |  linear RMSE %.6f", eng::io::rmse(ha, hb));
        std::printf("\n");
        if (!heatmap.empty())
            eng::io::writePng(heatmap, eng::io::quantizeToU8(eng::io::errorHeatmap(da, db, scale)));
    } catch (const eng::io::IoError& e) {
        std::fprintf(stderr, "imgdiff: %s\n", e.what());
        return 2;
    }
    return 0;
}
