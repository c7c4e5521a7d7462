#include "report_html.h"

#include "claims.h"
#include "light_axis.h"
#include "report_crops.h"
#include "report_script.h"

#include "agaa/methods.h"
#include "engine/io/io_error.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>

#ifndef AGAA_BENCH_CHARTJS
#define AGAA_BENCH_CHARTJS "/usr/share/javascript/chart.js/chart.min.js"
#endif

namespace agaa::bench {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr uint32_t kCropDisplayPixels = 128; // on-page width of a crop

const char* kStyle = R"CSS(
body { font: 14px/1.4 system-ui, sans-serif; margin: 0 auto; max-width: 1500px; padding: 0 16px 40px; color: #222; }
h1 { margin-bottom: 4px; } h2 { border-bottom: 1px solid #ccc; padding-bottom: 2px; margin-top: 32px; }
.meta { color: #555; } .warn { color: #a40; } .quote { color: #555; font-style: italic; }
table { border-collapse: collapse; margin: 8px 0; } th, td { border: 1px solid #ddd; padding: 3px 6px; vertical-align: top; }
th { background: #f4f4f4; } td.num { text-align: right; font-variant-numeric: tabular-nums; white-space: nowrap; }
table.jobs { font-size: 12px; } .small { font-size: 12px; color: #555; }
.charts { display: grid; grid-template-columns: repeat(auto-fill, minmax(460px, 1fr)); gap: 16px; }
figure { margin: 0; } .chart { position: relative; height: 340px; } figcaption { font-size: 12px; color: #555; }
.crop { display: block; position: relative; overflow: hidden; }
.crop img, .cmp img { position: absolute; image-rendering: pixelated; max-width: none; }
.cmp { position: relative; overflow: hidden; }
.cmp-top { position: absolute; inset: 0; border-right: 1px solid #fff; }
.cmp-top .h { display: none; } table.show-heat .cmp-top .h { display: block; } table.show-heat .cmp-top .m { display: none; }
.cmp-slider { position: absolute; bottom: 0; left: 0; width: 100%; margin: 0; opacity: 0.8; }
table.crops td { padding: 2px; } table.crops td.label { font-size: 12px; max-width: 140px; }
)CSS";

std::string esc(const std::string& s) {
    std::string out;
    for (char c : s) {
        switch (c) {
        case '&':
            out += "&amp;";
            break;
        case '<':
            out += "&lt;";
            break;
        case '>':
            out += "&gt;";
            break;
        case '"':
            out += "&quot;";
            break;
        default:
            out += c;
        }
    }
    return out;
}

std::string num(double v, int precision = 3) {
    if (std::isinf(v)) return v > 0 ? "&infin;" : "-&infin;";
    if (std::isnan(v)) return "&ndash;";
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", precision, v);
    return buf;
}

// "n8 c2", "n8 S3", "n8", or "" for a method that takes none.
std::string setting(const Job& j) {
    std::string s;
    if (j.usesSamples) s += "n" + std::to_string(j.samples);
    if (j.usesAggregates) s += (s.empty() ? "" : " ") + std::string("c") + std::to_string(j.aggregates);
    if (j.surfaces) s += (s.empty() ? "" : " ") + std::string("S") + std::to_string(j.surfaces);
    if (!j.tolerance.empty()) s += (s.empty() ? "" : " ") + std::string("T") + j.tolerance;
    if (j.specularAA) s += (s.empty() ? "" : " ") + std::string("+ specular AA");
    return s;
}

std::string label(const Job& j) {
    const std::string s = setting(j);
    return s.empty() ? j.method : j.method + " " + s;
}

// "reference.gbuffer.opaque" -> "gbuffer", "fxaa.noaa.lighting" -> "lighting", "readback.hdr" ->
// "readback": one colour per stage, whichever method (or method it builds on) owns the pass.
std::string passGroup(const std::string& pass) {
    std::vector<std::string> parts;
    std::stringstream s(pass);
    for (std::string part; std::getline(s, part, '.');)
        parts.push_back(part);
    if (parts.size() < 2 || parts[0] == "readback") return parts.empty() ? pass : parts[0];
    for (size_t i = 1; i < parts.size(); ++i)
        if (!isKnownMethod(parts[i])) return parts[i];
    return parts.back();
}

std::vector<std::string> scenesOf(const std::vector<JobResult>& results) {
    std::vector<std::string> scenes;
    for (const JobResult& r : results)
        if (std::find(scenes.begin(), scenes.end(), r.job.scene) == scenes.end())
            scenes.push_back(r.job.scene);
    return scenes;
}

std::string readFile(const fs::path& file) {
    std::ifstream f(file, std::ios::binary);
    if (!f) throw eng::io::IoError("cannot read " + file.string());
    std::ostringstream s;
    s << f.rdbuf();
    return s.str();
}

// The chart data the page's script reads.
json benchData(const std::vector<JobResult>& results) {
    json jobs = json::array();
    std::vector<std::string> groups, methods;
    for (const MethodInfo& m : knownMethods())
        methods.push_back(m.name);
    for (const JobResult& r : results) {
        if (std::find(methods.begin(), methods.end(), r.job.method) == methods.end())
            methods.push_back(r.job.method);
        json passes = json::object();
        for (const PassTime& p : r.passes) {
            const std::string g = passGroup(p.name);
            if (std::find(groups.begin(), groups.end(), g) == groups.end()) groups.push_back(g);
            passes[g] = passes.value(g, 0.0) + p.ms.median;
        }
        jobs.push_back(
            {{"scene", r.job.scene},
             {"method", r.job.method},
             {"label", label(r.job)},
             {"setting", setting(r.job)},
             {"series", r.job.method + (r.job.usesAggregates ? " c" + std::to_string(r.job.aggregates) : "") +
                            (r.job.surfaces ? " S" + std::to_string(r.job.surfaces) : "") +
                            (r.job.tolerance.empty() ? "" : " T" + r.job.tolerance) +
                            (r.job.specularAA ? " + specular AA" : "")},
             // The knob's curve (report_script.cpp): the jobs that differ only in AGAA's tolerance.
             {"knob", r.job.usesAggregates && r.job.method.rfind("agaa", 0) == 0 && !r.job.specularAA
                          ? json(r.job.method + " n" + std::to_string(r.job.samples) + " c" +
                                 std::to_string(r.job.aggregates))
                          : json()},
             {"n", r.job.samples},
             {"c", r.job.aggregates},
             {"usesSamples", r.job.usesSamples},
             {"frameMs", r.frameMs.median},
             {"frameMin", r.frameMs.min},
             {"frameMax", r.frameMs.max},
             {"bpp", r.bytesPerPixel},
             {"rmse", r.errorTruth ? json(r.errorTruth->rmse) : json(nullptr)},
             // The error bar: the truth's own error bounds how far the measured error can be off.
             {"rmseBar", std::isfinite(r.truth.errorEstimate) ? json(r.truth.errorEstimate) : json(nullptr)},
             {"passes", passes}});
    }
    return {{"jobs", jobs}, {"methods", methods}, {"passGroups", groups}};
}

std::string chartFigure(const std::string& scene, const std::string& kind, const std::string& caption) {
    return "<figure><div class=\"chart\"><canvas data-chart=\"" + kind + "\" data-scene=\"" + esc(scene) +
           "\"></canvas></div><figcaption>" + caption + "</figcaption></figure>\n";
}

// An <img> showing only `w` of the full image, scaled to kCropDisplayPixels wide.
std::string cropImage(const std::string& src, const Window& w, const SceneCrops& crops,
                      const char* cls = "") {
    const double s = double(kCropDisplayPixels) / double(w.width);
    char style[256];
    std::snprintf(style, sizeof style, "width:%.1fpx;height:%.1fpx;left:%.1fpx;top:%.1fpx", crops.width * s,
                  crops.height * s, -double(w.x) * s, -double(w.y) * s);
    return "<img class=\"" + std::string(cls) + "\" src=\"" + esc(src) + "\" style=\"" + style +
           "\" alt=\"\">";
}

std::string cropBox(const std::string& src, const Window& w, const SceneCrops& crops) {
    const double h = double(w.height) * kCropDisplayPixels / double(w.width);
    return "<a class=\"crop\" href=\"" + esc(src) +
           "\" title=\"open the full image\" style=\"width:" + std::to_string(kCropDisplayPixels) +
           "px;height:" + num(h, 1) + "px\">" + cropImage(src, w, crops) + "</a>";
}

std::string compareBox(const JobResult& r, const Window& w, const SceneCrops& crops) {
    const double h = double(w.height) * kCropDisplayPixels / double(w.width);
    return "<div class=\"cmp\" style=\"width:" + std::to_string(kCropDisplayPixels) +
           "px;height:" + num(h, 1) + "px\">" + cropImage(r.imageTruth, w, crops) +
           "<div class=\"cmp-top\">" + cropImage(r.imageDisplay, w, crops, "m") +
           cropImage(r.imageHeatmap, w, crops, "h") +
           "</div><input class=\"cmp-slider\" type=\"range\" min=\"0\" max=\"100\" value=\"50\" "
           "title=\"slide: method (left) over truth (right)\"></div>";
}

std::string cropSection(const SceneCrops& crops, const std::vector<const JobResult*>& jobs,
                        size_t sceneIndex) {
    std::ostringstream h;
    h << "<h3>Where the methods differ most</h3>\n";
    if (crops.windows.empty()) {
        h << "<p class=\"small\">" << esc(crops.note.empty() ? "no window differs" : crops.note) << "</p>\n";
        return h.str();
    }
    const std::string tableId = "crops-" + std::to_string(sceneIndex);
    const JobResult& first = *jobs.front();
    h << "<p class=\"small\">Windows of " << crops.windows[0].width << "x" << crops.windows[0].height
      << " pixels where the per-pixel error against the converged truth (" << first.truth.supersampling << "x"
      << first.truth.supersampling << " tiles at n=" << first.truth.samples
      << ") varies most between the methods. Per window: the method, its error heatmap (error x"
      << num(first.heatmapScale, 0)
      << ": black 0, blue, red, yellow, white >= " << num(1.0 / first.heatmapScale, 2)
      << "), and a slider over the truth. Click a crop for the full image. "
      << "<button class=\"cmp-toggle\" data-table=\"" << tableId
      << "\">slider: method over truth</button></p>\n";
    h << "<table class=\"crops\" id=\"" << tableId << "\"><tr><th>truth " << first.truth.supersampling << "x"
      << first.truth.supersampling << ", n=" << first.truth.samples << "</th>";
    for (size_t k = 0; k < crops.windows.size(); ++k) {
        const Window& w = crops.windows[k];
        h << "<th colspan=\"3\">window " << k + 1 << " at (" << w.x << ", " << w.y << "), spread "
          << num(w.meanError, 3) << "<br>" << cropBox(first.imageTruth, w, crops) << "</th>";
    }
    h << "</tr>\n";
    for (const JobResult* r : jobs) {
        h << "<tr><td class=\"label\"><b>" << esc(label(r->job)) << "</b><br>RMSE "
          << (r->errorTruth ? num(r->errorTruth->rmse, 4) : "&ndash;") << "<br><a href=\""
          << esc(r->imageDisplay) << "\">image</a> <a href=\"" << esc(r->imageHeatmap) << "\">error</a></td>";
        for (const Window& w : crops.windows)
            h << "<td>" << cropBox(r->imageDisplay, w, crops) << "</td><td>"
              << cropBox(r->imageHeatmap, w, crops) << "</td><td>" << compareBox(*r, w, crops) << "</td>";
        h << "</tr>\n";
    }
    h << "</table>\n";
    return h.str();
}

std::string errorCells(const std::optional<ErrorMetrics>& e) {
    if (!e) return "<td class=\"num\" colspan=\"5\">&ndash;</td>";
    return "<td class=\"num\">" + num(e->rmse, 4) + "</td><td class=\"num\">" +
           (e->flip ? num(*e->flip, 4) : "&ndash;") + "</td><td class=\"num\">" + num(e->psnr, 1) +
           "</td><td class=\"num\">" + num(e->ssim, 4) + "</td><td class=\"num\">" + num(e->p99, 3) + "</td>";
}

std::string jobsTable(const std::vector<JobResult>& results) {
    std::ostringstream h;
    const TruthInfo truth = results.empty() ? TruthInfo{} : results.front().truth;
    h << "<table class=\"jobs\"><tr><th rowspan=\"2\">scene</th><th rowspan=\"2\">method</th><th "
         "rowspan=\"2\">n</th>"
         "<th rowspan=\"2\">c</th><th colspan=\"2\">frame GPU ms</th><th rowspan=\"2\">shading pass ms</th>"
         "<th rowspan=\"2\">bytes / pixel</th><th colspan=\"2\">shading events / pixel</th>"
         "<th colspan=\"5\">vs reference at the same n</th><th colspan=\"5\">vs converged truth ("
      << truth.supersampling << "x" << truth.supersampling << " tiles at n=" << truth.samples
      << ")</th><th rowspan=\"2\">truth's<br>own error</th><th rowspan=\"2\">linear mean<br>/ "
         "truth's</th><th "
         "rowspan=\"2\">temporal<br>&Delta;error</th><th rowspan=\"2\">moving:<br>path RMSE</th><th "
         "rowspan=\"2\">moving:<br>path &#xA7FB;LIP</th>"
         "<th rowspan=\"2\">moving:<br>ghosting</th>"
         "<th rowspan=\"2\">valid.<br>errors</th>"
         "<th rowspan=\"2\">images</th></tr>\n<tr><th>median</th><th>min..max</th><th>mean</th><th>max</th>"
         "<th>RMSE</th><th>&#xA7FB;LIP</th><th>PSNR "
         "dB</th><th>SSIM</th><th>p99</th><th>RMSE</th><th>&#xA7FB;LIP</th><th>PSNR "
         "dB</th><th>SSIM</th><th>p99</th></tr>\n";
    for (const JobResult& r : results) {
        std::string passes;
        for (const PassTime& p : r.passes)
            passes += p.name + ": " + num(p.ms.median) + " ms\n";
        const std::optional<double> shading = shadingPassMs(r);
        h << "<tr><td>" << esc(r.job.scene) << "</td><td>" << esc(r.job.method) << "</td><td class=\"num\">"
          << (r.job.usesSamples ? std::to_string(r.job.samples) : "&ndash;") << "</td><td class=\"num\">"
          << (r.job.usesAggregates ? std::to_string(r.job.aggregates)
              : r.job.surfaces     ? "S = " + std::to_string(r.job.surfaces)
                                   : std::string("&ndash;"))
          << "</td><td class=\"num\" title=\"" << esc(passes) << "\">" << num(r.frameMs.median)
          << "</td><td class=\"num\">" << num(r.frameMs.min) << ".." << num(r.frameMs.max)
          << "</td><td class=\"num\">" << (shading ? num(*shading) : "&ndash;") << "</td><td class=\"num\">"
          << num(r.bytesPerPixel, 1) << "</td><td class=\"num\">" << num(r.shadingEventsMean, 2)
          << "</td><td class=\"num\">" << r.shadingEventsMax << "</td>" << errorCells(r.errorSameN)
          << errorCells(r.errorTruth) << "<td class=\"num\">"
          << (std::isfinite(r.truth.errorEstimate) ? num(r.truth.errorEstimate, 4) : "unknown")
          << "</td><td class=\"num\">"
          << (r.truth.meanLuminance > 0.0 ? num(r.meanLuminance / r.truth.meanLuminance, 3) : "&ndash;")
          << "</td><td class=\"num\">" << (r.temporal ? num(r.temporal->meanErrorChange, 5) : "&ndash;")
          << "</td><td class=\"num\">"
          << (r.temporal && !r.temporal->pathError.empty() ? num(r.temporal->meanPathError, 4) : "&ndash;")
          << "</td><td class=\"num\">"
          << (r.temporal && r.temporal->meanPathFlip > 0.0 ? num(r.temporal->meanPathFlip, 4) : "&ndash;")
          << "</td><td class=\"num\">"
          << (r.temporal && r.temporal->disoccludedPixels ? num(r.temporal->ghostingError, 4) : "&ndash;")
          << "</td><td class=\"num\">" << (r.validationEnabled ? std::to_string(r.validationErrors) : "off")
          << "</td><td><a href=\"" << esc(r.imageDisplay) << "\">image</a> <a href=\"" << esc(r.imageHeatmap)
          << "\">error</a></td></tr>\n";
    }
    h << "</table>\n";
    return h.str();
}

std::string claimsTable(const std::vector<JobResult>& results) {
    std::ostringstream h;
    h << "<table><tr><th>claim</th><th>quoted (not measured here)</th><th>measured in this run "
         "(lavapipe)</th></tr>\n";
    for (const ClaimRow& c : measureClaims(results)) {
        std::string detail;
        for (const std::string& s : c.perScene)
            detail += (detail.empty() ? "" : ", ") + s;
        h << "<tr><td>" << esc(c.claim) << "</td><td class=\"quote\">" << esc(c.quoted) << "</td><td><b>"
          << esc(c.measured) << "</b>";
        if (!detail.empty()) h << "<br><span class=\"small\">" << esc(detail) << "</span>";
        if (!c.missing.empty()) h << "<br><span class=\"small\">needs " << esc(c.missing) << "</span>";
        h << "</td></tr>\n";
    }
    h << "</table>\n";
    return h.str();
}

// The light-count axis: frame ms and the ratio to Simple/Complex per K, and where it crosses 1.
std::string lightAxisSection(const std::vector<LightAxisTable>& tables,
                             const std::vector<LightAxisTable>& shadingTables) {
    std::ostringstream h;
    h << "<section id=\"lights\"><h2>Light count: where each method crosses Simple/Complex</h2>\n"
         "<p class=\"small\">Each scene with K generated point lights added (agaa-render --extra-lights: a "
         "Halton sequence in the bounds grown by a tenth of their diagonal, each light giving its "
         "neighbourhood the key light's illuminance). Cells: median GPU ms of the frame (first tables) or of "
         "the shading pass &ldquo;&lt;method&gt;.lighting&rdquo; where the light count acts (second tables), "
         "and in brackets the ratio "
         "to Simple/Complex at the same n and K (below 1: faster; ~: the two jobs' frame-time quartiles "
         "overlap, so the order is within this run's timing spread). The crossing is the first measured K on "
         "the other side of 1 beyond the spread, with the ratio interpolated linearly in K between the two "
         "measured counts.</p>\n";
    std::vector<std::pair<const LightAxisTable*, const char*>> all;
    for (const LightAxisTable& t : tables)
        all.push_back({&t, "frame"});
    for (const LightAxisTable& t : shadingTables)
        all.push_back({&t, "shading pass"});
    for (const auto& [table, what] : all) {
        const LightAxisTable& t = *table;
        h << "<h3>" << esc(t.scene) << ": " << what << " GPU ms</h3>\n<table class=\"lights\" data-scene=\""
          << esc(t.scene) << "\" data-measure=\"" << what << "\"><tr><th>method</th><th>n</th><th>c</th>";
        for (uint32_t k : t.lightCounts)
            h << "<th>K = " << k << "</th>";
        h << "<th>against Simple/Complex</th></tr>\n";
        for (const LightAxisRow& r : t.rows) {
            h << "<tr><td>" << esc(r.method) << "</td><td class=\"num\">"
              << (r.usesSamples ? std::to_string(r.samples) : "&ndash;") << "</td><td class=\"num\">"
              << (r.usesAggregates ? std::to_string(r.aggregates)
                  : r.surfaces     ? "S = " + std::to_string(r.surfaces)
                                   : std::string("&ndash;"))
              << "</td>";
            for (size_t i = 0; i < t.lightCounts.size(); ++i) {
                h << "<td class=\"num\">" << (r.frameMs[i] ? num(*r.frameMs[i], 2) : "&ndash;");
                if (r.ratioToPeer[i])
                    h << " (" << num(*r.ratioToPeer[i], 2) << (r.beyondSpread[i] ? "" : "~") << ")";
                h << "</td>";
            }
            h << "<td" << (r.crossesAt ? " class=\"cross\"" : "") << ">" << esc(r.verdict) << "</td></tr>\n";
        }
        h << "</table>\n";
    }
    h << "</section>\n";
    return h.str();
}

} // namespace

fs::path findChartJs() {
    fs::path path = AGAA_BENCH_CHARTJS;
    if (const char* env = std::getenv("AGAA_CHARTJS"); env && *env) path = env;
    if (!fs::is_regular_file(path))
        throw eng::io::IoError(
            "Chart.js not found at " + path.string() +
            ": the report inlines it; install the Debian package libjs-chart.js (tools/deps.sh) or "
            "set AGAA_CHARTJS to a chart.min.js");
    return path;
}

void writeReport(const fs::path& outDir, const std::vector<JobResult>& results, const fs::path& chartJs,
                 const ReportInfo& info) {
    const std::string chartJsText = readFile(chartJs);
    const std::vector<std::string> scenes = scenesOf(results);
    const std::vector<SceneCrops> crops = chooseCrops(outDir, results);
    std::set<std::string> devices;
    for (const JobResult& r : results)
        devices.insert(r.device);

    std::ostringstream h;
    h << "<!doctype html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>AGAA benchmark: what "
         "accuracy "
         "costs in time</title>\n<style>"
      << kStyle << "</style>\n<script>/* Chart.js, MIT licence, inlined from " << esc(chartJs.string())
      << " */\n"
      << chartJsText << "\n</script></head>\n<body>\n<h1>What accuracy costs in time</h1>\n";
    h << "<p class=\"meta\">" << results.size() << " jobs on " << scenes.size() << " scene(s)";
    if (!results.empty()) {
        const JobResult& f = results.front();
        h << ", " << f.width << "x" << f.height << ", " << f.warmupFrames << " warm-up + " << f.timedFrames
          << " timed frame(s) per job";
    }
    for (const std::string& d : devices)
        h << ", device " << esc(d);
    h << ".<br>Started as <code>" << esc(info.command)
      << "</code>. Every number on this page was measured in that "
      << "run, except the quoted figures in the claims table.<br>All error metrics are computed on the "
         "tone-mapped "
         "display image, sRGB-encoded, values in [0,1].</p>\n";
    for (const std::string& w : info.warnings)
        h << "<p class=\"warn\">" << esc(w) << "</p>\n";
    h << "<nav>Scenes:";
    for (const std::string& s : scenes)
        h << " <a href=\"#scene-" << esc(s) << "\">" << esc(s) << "</a>";
    h << " | <a href=\"#claims\">claims</a>"
      << (lightAxisTables(results).empty() ? "" : " | <a href=\"#lights\">light count</a>")
      << " | <a href=\"#jobs\">every job</a> | <a href=\"#how\">method</a> "
         "| "
         "<a href=\"results.json\">results.json</a> <a href=\"results.csv\">results.csv</a></nav>\n";

    h << "<section id=\"claims\"><h2>Headline figures: quoted vs measured</h2>\n"
      << "<p class=\"small\">The quoted ratios come from the AGAA paper and talks (GTX 980, OpenGL, "
         "1280x720). "
         "The measured ones come from this run on a software rasteriser, at this run's size; ranges are over "
         "scenes. Shading pass = the pass named &ldquo;&lt;method&gt;.lighting&rdquo; (shadow-map "
         "passes are not shading).</p>\n"
      << claimsTable(results) << "</section>\n";
    const std::vector<LightAxisTable> lightTables = lightAxisTables(results);
    if (!lightTables.empty())
        h << lightAxisSection(lightTables, lightAxisTables(results, LightAxisMeasure::ShadingPass));

    for (size_t i = 0; i < scenes.size(); ++i) {
        const std::string& scene = scenes[i];
        std::vector<const JobResult*> jobs;
        std::set<uint32_t> ns;
        for (const JobResult& r : results)
            if (r.job.scene == scene) {
                jobs.push_back(&r);
                if (r.job.usesSamples) ns.insert(r.job.samples);
            }
        h << "<section id=\"scene-" << esc(scene) << "\"><h2>Scene: " << esc(scene)
          << "</h2>\n<div class=\"charts\">\n"
          << chartFigure(scene, "time",
                         "Accuracy vs time: one point per method and setting; dashed: Pareto front "
                         "(no other point is both faster and more accurate).")
          << chartFigure(scene, "memory",
                         "Accuracy vs memory: bytes per pixel of each technique's own storage, "
                         "from its real allocations.")
          << chartFigure(scene, "passes",
                         "Per-pass GPU time (median over the timed frames), stacked per job.");
        if (ns.size() > 1)
            h << chartFigure(scene, "growth-time", "How frame time grows with n (dash length: c).")
              << chartFigure(scene, "growth-memory", "How storage grows with n (dash length: c).");
        h << "</div>\n";
        const auto it =
            std::find_if(crops.begin(), crops.end(), [&](const SceneCrops& c) { return c.scene == scene; });
        if (it != crops.end()) h << cropSection(*it, jobs, i);
        h << "</section>\n";
    }

    h << "<section id=\"jobs\"><h2>Every job</h2>\n<p class=\"small\">Hover a frame time for its passes. "
         "Temporal &Delta;error: mean over pixels and channels of |e<sub>t</sub> - e<sub>t-1</sub>| with e "
         "the signed "
         "error against the converged truth at each frame of the camera path.</p>\n"
      << jobsTable(results) << "</section>\n";

    const JobResult* any = results.empty() ? nullptr : &results.front();
    h << "<section id=\"how\"><h2>How these numbers were measured</h2><ul>\n"
         "<li>GPU times: timestamps around every pass; the median over the timed frames after the warm-up "
         "frames "
         "(lavapipe JIT-compiles a pipeline on first use). Frame time = the sum of that frame's pass times, "
         "including the read-back copies every method pays alike.</li>\n"
         "<li>Errors: RMSE, the mean &#xA7FB;LIP (LDR, Andersson et al. 2020, at 67 pixels a degree: a "
         "0.7 m wide 4K monitor seen from 0.7 m; it charges blur and lost edges that RMSE averages away), "
         "PSNR, SSIM (11x11 Gaussian window on luma) and the 99th percentile of the per-pixel max-channel "
         "error, all on the tone-mapped display image, sRGB-encoded.</li>\n"
         "<li>Ground truths: the reference (per-sample shading) at the same n, for methods that take n (the "
         "reference itself is listed with error 0 by definition): the shading error at fixed visibility; and "
         "the converged truth: the reference at n="
      << (any ? any->truth.samples : 32) << " with materials shaded per sample, at "
      << (any ? any->truth.supersampling : 4) << " times the width and height in tiles, each block averaged ("
      << (any ? any->truth.samples * any->truth.supersampling * any->truth.supersampling : 512)
      << " samples a pixel). Its own error is estimated as half the display RMSE between its two "
         "checkerboard halves, drawn as error bars on the charts; a claim whose two errors differ by less "
         "than ten times it reads undecided.</li>\n";
    if (any && any->temporal)
        h << "<li>Temporal stability: " << any->temporal->frames
          << (any->temporal->path == "truck"
                  ? " frames trucking the camera sideways in steps of " +
                        num(100.0 * any->temporal->stepFraction, 2) + " % of the scene's bounds diagonal"
                  : " frames orbiting the scene's bounds centre in " + num(any->temporal->stepDegrees, 2) +
                        "&deg; steps")
          << ", rendered at " << any->temporal->width << "x" << any->temporal->height
          << ", each frame against its own converged truth: &Delta;error is the flicker the truth does not "
             "have, path RMSE the mean error a user who moves sees, ghosting the RMSE on the pixels the "
             "frame "
             "before did not see (a temporal method's history there is another surface's)"
          << (any->temporal->disoccludedPixels
                  ? ": " + std::to_string(any->temporal->disoccludedPixels) + " pixels over the path"
                  : std::string())
          << ". The other error columns are still "
             "frames, where a temporal method (taa, agaa-taa) has converged over the warm-up and timed "
             "frames.</li>\n";
    else
        h << "<li>Temporal stability: not measured in this run (--temporal 0).</li>\n";
    h << "<li>Bytes per pixel: the technique's own per-pixel resources, from the sizes of their device "
         "allocations.</li>\n</ul></section>\n";

    std::string data = benchData(results).dump();
    for (size_t p = data.find("</"); p != std::string::npos; p = data.find("</", p + 2))
        data.replace(p, 2, "<\\/");
    h << "<script>const BENCH = " << data << ";</script>\n<script>" << reportScript()
      << "</script>\n</body></html>\n";
    writeTextFile(outDir / "report.html", h.str());
}

} // namespace agaa::bench
