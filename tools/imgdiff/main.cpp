// imgdiff: compares two EXR renders. Prints RMSE, PSNR, SSIM and the 99th-percentile error
// on the display image (ACES tone map + sRGB, the project's display transform) and the RMSE
// of the linear HDR values; optionally writes an error heatmap PNG.
//   imgdiff A.exr B.exr [--heatmap OUT.png] [--scale S]
// Exit codes: 0 compared; 2 bad arguments or unreadable/mismatched images.

#include "engine/io/exr.h"
#include "engine/io/io_error.h"
#include "engine/io/metrics.h"
#include "engine/io/png.h"
#include "engine/io/tone_map.h"

#include <cmath>
#include <cstdio>
#include <string>

int main(int argc, char** argv) {
    std::string a, b, heatmap;
    float scale = 4.0f;
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
        } else if (arg == "--help" || arg == "-h") {
            std::printf("usage: imgdiff A.exr B.exr [--heatmap OUT.png] [--scale S]\n");
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
        eng::io::ImageF ha = eng::io::readExr(a), hb = eng::io::readExr(b);
        eng::io::ImageF da = eng::io::toneMapped(ha), db = eng::io::toneMapped(hb);
        std::printf("display RMSE %.6f  PSNR %.2f dB  SSIM %.5f  p99 %.5f  |  linear RMSE %.6f\n",
                    eng::io::rmse(da, db), eng::io::psnr(da, db), eng::io::ssim(da, db),
                    eng::io::percentileAbsError(da, db, 99.0), eng::io::rmse(ha, hb));
        if (!heatmap.empty())
            eng::io::writePng(heatmap, eng::io::quantizeToU8(eng::io::errorHeatmap(da, db, scale)));
    } catch (const eng::io::IoError& e) {
        std::fprintf(stderr, "imgdiff: %s\n", e.what());
        return 2;
    }
    return 0;
}
