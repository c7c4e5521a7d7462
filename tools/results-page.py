#!/usr/bin/env python3
"""docs/results.md and the README's headline table, from one recorded agaa-bench run.

  tools/results-page.py --record DIR -- AGAA-BENCH --out DIR [flags]
      runs the bench command and writes DIR/run.json beside its output: the command, its wall
      time, the machine (CPU model, cores, Mesa) and the git commit.
  tools/results-page.py DIR --write FILE [--readme README.md]
      writes the results page from DIR (run.json and the results.json agaa-bench wrote) and,
      with --readme, replaces the README's block between the headline markers with the page's.
  tools/results-page.py --check [--page docs/results.md] [--readme README.md]
      exits 1, saying where, when the page's headline table is not the one its own data
      implies, or the README's block is not the page's. Needs no bench output.

Errors are display RMSE against the converged truth (docs/truth.md). Python 3 standard
library only.
"""

import argparse
import datetime
import json
import os
import shlex
import subprocess
import sys
import textwrap
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BEGIN = "<!-- results:headline begin -->"
END = "<!-- results:headline end -->"
DATA_BEGIN = "<!-- results:data"
DATA_END = "-->"
JOB_SCHEMA = "agaa-bench-job/2"
RESULTS_SCHEMA = "agaa-bench-results/2"
# Two errors against one truth differ by a measured amount only where the truth's own error cannot
# account for their difference: 2.5 times it (tools/agaa_bench/claims.cpp, kDecidedDifferenceRatio).
DECIDED_RATIO = 2.5
METHOD_ORDER = ["noaa", "fxaa", "taa", "reference", "simple-complex", "simple-complex-naive", "sbaa",
                "streaming", "agaa", "agaa-taa", "agaa-samples", "agaa-accumulate"]
AGAA = "agaa"


class Refused(Exception):
    pass


def method_label(job):
    """The method and its setting, and " + specular AA" for a job of the specular-AA axis."""
    return base_label(job) + (" + specular AA" if job.get("specular_aa") else "")


def base_label(job):
    m, n, c, s = job["method"], job["samples"], job["aggregates"], job["surfaces"]
    names = {"noaa": "no-AA", "fxaa": "FXAA", "taa": "TAA", "reference": "reference", "simple-complex": "Simple/Complex",
             "simple-complex-naive": "Simple/Complex naive", "sbaa": "SBAA", "streaming": "streaming",
             "agaa": "AGAA", "agaa-taa": "AGAA + TAA", "agaa-samples": "AGAA samples path", "agaa-accumulate": "AGAA accumulate path"}
    name = names.get(m, m)
    if not job["uses_samples"]:
        return name
    if job["uses_aggregates"]:
        tolerance = job.get("tolerance") or ""
        return f"{name} ({n}, {c})" + (f", tolerance {tolerance}" if tolerance else "")
    if s:
        return f"{name} ({n}, S = {s})"
    return f"{name} ({n})"


def method_rank(job):
    m = job["method"]
    return (METHOD_ORDER.index(m) if m in METHOD_ORDER else len(METHOD_ORDER), m, job["samples"],
            job["aggregates"], job["surfaces"], job.get("tolerance") or "", bool(job.get("specular_aa")))


def at_defaults(job):
    """Not a job of AGAA's tolerance axis: the headline compares each method at its defaults (with
    and without specular anti-aliasing, what a user would switch on)."""
    return not job.get("tolerance")


# ---- recording a run ----------------------------------------------------------------------

def run_text(args, strip=True):
    try:
        out = subprocess.run(args, capture_output=True, text=True, check=True, cwd=ROOT).stdout
        return out.strip() if strip else out
    except (OSError, subprocess.CalledProcessError):
        return ""


def machine():
    cpu = "unknown CPU"
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    cpu = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    mesa = run_text(["dpkg-query", "-W", "-f", "${Version}", "mesa-vulkan-drivers"])
    # Other work on the machine slows lavapipe's frames: the load when the run started says how much.
    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else -1.0
    return {"cpu": cpu, "cores": os.cpu_count() or 0, "mesa": mesa or "unknown",
            "load_at_start": round(load, 2)}


def commit():
    head = run_text(["git", "rev-parse", "HEAD"])
    # What the working tree held beyond the commit, pages (*.md) aside: the binary may include it.
    # Not stripped: each porcelain line starts with its two status columns, which may be blank.
    status = run_text(["git", "status", "--porcelain"], strip=False)
    changed = sorted(line[3:] for line in status.splitlines() if line[3:] and not line.endswith(".md"))
    return {"commit": head or "unknown", "uncommitted_changes": changed}


def record(out_dir, command):
    if not command:
        raise Refused("--record DIR needs the bench command after --")
    started = datetime.datetime.now(datetime.timezone.utc)
    t0 = time.monotonic()
    rc = subprocess.call(command)
    seconds = time.monotonic() - t0
    # The allocator settings lavapipe's frame times depend on (tools/run.sh sets them) belong to the command.
    env = [f"{k}={os.environ[k]}" for k in sorted(os.environ) if k.startswith("MALLOC_")]
    info = {"command": " ".join(env + [shlex.join(command)]),
            "started_utc": started.strftime("%Y-%m-%d %H:%M UTC"),
            "wall_s": round(seconds, 1), "exit_status": rc, "machine": machine(), "git": commit()}
    os.makedirs(out_dir, exist_ok=True)
    with open(os.path.join(out_dir, "run.json"), "w") as f:
        json.dump(info, f, indent=2)
        f.write("\n")
    print(f"results-page: the bench took {seconds:.0f} s (exit status {rc}); "
          f"recorded in {os.path.join(out_dir, 'run.json')}")
    return rc


# ---- reading a run ------------------------------------------------------------------------

def load_run(out_dir):
    run_file = os.path.join(out_dir, "run.json")
    if not os.path.isfile(run_file):
        raise Refused(f"{run_file} is missing: record the run with "
                      f"tools/results-page.py --record {out_dir} -- AGAA-BENCH --out {out_dir} ...")
    with open(run_file) as f:
        run = json.load(f)
    if run.get("exit_status", 0) != 0:
        raise Refused(f"{run_file}: the recorded bench run exited with status {run['exit_status']}")
    # results.json holds exactly the jobs of the run's plan; DIR/jobs/ may hold an earlier sweep's too.
    results_file = os.path.join(out_dir, "results.json")
    try:
        with open(results_file) as f:
            results = json.load(f)
    except (OSError, json.JSONDecodeError) as err:
        raise Refused(f"{results_file}: {err}")
    if results.get("schema") != RESULTS_SCHEMA:
        raise Refused(f"{results_file}: schema is {results.get('schema')!r}, not {RESULTS_SCHEMA!r}")
    jobs = results.get("jobs", [])
    for j in jobs:
        if j.get("schema") != JOB_SCHEMA:
            raise Refused(f"{results_file}: job {j.get('id')}: schema is {j.get('schema')!r}, "
                          f"not {JOB_SCHEMA!r}")
        if j.get("error_vs_truth") is None:
            raise Refused(f"{results_file}: job {j['id']} has no error against the truth")
    if not jobs:
        raise Refused(f"{results_file} holds no jobs")
    return run, jobs


def scene_order(jobs):
    seen = []
    for j in sorted(jobs, key=lambda j: j["plan_index"]):
        if j["scene"] not in seen:
            seen.append(j["scene"])
    return seen


def headline_data(jobs):
    """What the headline table needs, small enough to keep in the page itself."""
    scenes = []
    for scene in scene_order(jobs):
        rows = sorted((j for j in jobs if j["scene"] == scene and at_defaults(j)), key=method_rank)
        scenes.append({
            "scene": scene,
            "truth_error": round(rows[0]["truth"]["error_estimate"], 6),
            "methods": [method_data(j) for j in rows],
        })
        path = path_text(rows)
        if path:
            scenes[-1]["path"] = path
    return scenes


def path_text(rows):
    """The camera path the moving figures come from, in words."""
    t = next((j["temporal"] for j in rows if j.get("temporal") and j["temporal"].get("path_error")), None)
    if not t:
        return None
    if t.get("path") == "truck":
        return (f"{t['frames']} frames trucking sideways by {100.0 * t['step_fraction']:g} % of the scene's "
                f"bounds diagonal a frame, at {t['width']}x{t['height']}")
    return f"{t['frames']} frames orbiting in {t['step_degrees']:g} degree steps, at {t['width']}x{t['height']}"


def moving_error(job):
    """The camera path's mean error against each frame's own truth, or None without a path."""
    t = job.get("temporal")
    return t["mean_path_error"] if t and t.get("path_error") else None


def method_data(job):
    # AGAA at its defaults sets the frame-time budget; its specular-AA job is one of the others.
    m = {"label": method_label(job), "agaa": job["method"] == AGAA and not job.get("specular_aa"),
         "error": round(job["error_vs_truth"]["rmse"], 6),
         "frame_ms": round(job["timing"]["frame_gpu_ms"]["median"], 3),
         "frame_max_ms": round(job["timing"]["frame_gpu_ms"]["max"], 3)}
    if moving_error(job) is not None:
        m["moving"] = round(moving_error(job), 6)
    if "flip" in job["error_vs_truth"]:
        m["flip"] = round(job["error_vs_truth"]["flip"], 6)
    return m


# ---- the headline table -------------------------------------------------------------------

def verdict(scene, key="error"):
    """The method closest to the truth by `key` (the still error, "moving" or "flip") among those at
    or below AGAA's frame time: its slowest timed frame, the timing's own spread (lavapipe's medians
    within it are not ordered; AGAA + TAA is AGAA and one more pass)."""
    agaa = [m for m in scene["methods"] if m["agaa"]]
    if len(agaa) != 1:
        return "not judged: no AGAA job" if not agaa else "not judged: several AGAA jobs"
    budget = max(agaa[0]["frame_ms"], agaa[0].get("frame_max_ms", 0.0))
    within = sorted((m for m in scene["methods"] if m["frame_ms"] <= budget and m.get(key) is not None),
                    key=lambda m: m[key])
    if not within:
        return "not measured"
    best = within[0]
    if key == "flip":
        # The truth's own error is an RMSE, no bound on a FLIP difference: rank, and show the next.
        text = f"{best['label']} {best[key]:.3f}"
        return text + (f" (next {within[1]['label']} {within[1][key]:.3f})" if len(within) > 1 else "")
    bound = DECIDED_RATIO * scene["truth_error"]
    tied = [m for m in within if m[key] - best[key] < bound]
    if len(tied) == 1:
        return best["label"]
    return "undecided: " + ", ".join(m["label"] for m in tied)


def headline_block(data, run):
    scenes = [s["scene"] for s in data]
    labels = []
    for s in data:
        for m in s["methods"]:
            if m["label"] not in labels:
                labels.append(m["label"])
    lines = ["| | " + " | ".join(scenes) + " |", "|---" * (len(scenes) + 1) + "|",
             "| truth's own error | " + " | ".join(f"{s['truth_error']:.4f}" for s in data) + " |"]
    for label in labels:
        cells = []
        for s in data:
            m = next((m for m in s["methods"] if m["label"] == label), None)
            if m is None:
                cells.append("")
                continue
            moving = f" / {m['moving']:.4f}" if m.get("moving") is not None else ""
            flip = f", FLIP {m['flip']:.3f}" if m.get("flip") is not None else ""
            cell = f"{m['error']:.4f}{moving}{flip}, {m['frame_ms']:.0f} ms"
            cells.append(f"**{cell}**" if m["agaa"] else cell)
        lines.append(f"| {label} | " + " | ".join(cells) + " |")
    moving = any(m.get("moving") is not None for s in data for m in s["methods"])
    flip = any(m.get("flip") is not None for s in data for m in s["methods"])
    lines.append("| **closest to the truth at AGAA's frame time or less" + (", still" if moving else "") +
                 "** | " + " | ".join(verdict(s) for s in data) + " |")
    if moving:
        lines.append("| **closest at AGAA's frame time or less, moving** | " +
                     " | ".join(verdict(s, "moving") for s in data) + " |")
    if flip:
        lines.append("| **closest at AGAA's frame time or less, by FLIP** | " +
                     " | ".join(verdict(s, "flip") for s in data) + " |")
    g = run["git"]
    m = run["machine"]
    path = next((s["path"] for s in data if s.get("path")), None)
    measures = "Display RMSE against the converged truth"
    if moving:
        measures += (", still / moving (the mean over " + (path or "the camera path") +
                     ", each frame against its own truth: a temporal method's still frame has converged, a "
                     "user who moves sees the moving figure)")
    if flip:
        measures += (", the still frame's mean FLIP (Andersson et al. 2020, 67 pixels a degree; its row ranks "
                     "without ties, the truth's own FLIP error not being estimated)")
    caption = (f"{measures}, and frame time (median GPU ms on lavapipe, "
               f"{m['cpu']}, {m['cores']} cores, load average {m.get('load_at_start', 0.0):.1f}), per scene; "
               f"commit {g['commit'][:10]}. \"undecided\": the errors differ by less than "
               f"{DECIDED_RATIO:g} times the truth's own error. \"AGAA's frame time\": its slowest timed "
               "frame.")
    return "\n".join([BEGIN, wrap(caption), "", *lines, END])


# ---- the page -----------------------------------------------------------------------------

def wrap(text):
    return textwrap.fill(text, width=100, break_long_words=False, break_on_hyphens=False)


def pct(a, b):
    return f"{100.0 * (a - b) / b:+.1f} %" if b else ""


def job_table(rows):
    out = ["| method | frame ms, median [quartiles] | display RMSE vs truth | FLIP vs truth | moving: path RMSE "
           "| moving: ghosting | vs reference at the same n "
           "| SSIM vs truth | mean vs truth's | bytes/px | shading events/px, mean / worst lane |",
           "|---|---|---|---|---|---|---|---|---|---|---|"]
    for j in rows:
        f = j["timing"]["frame_gpu_ms"]
        same = j.get("error_vs_same_n_reference")
        ev = j["shading_events_per_pixel"]
        label = method_label(j)
        if j["method"] == AGAA:
            label = f"**{label}**"
        same_n = f"{same['rmse']:.4f}" if same else ""
        flip = f"{j['error_vs_truth']['flip']:.4f}" if "flip" in j["error_vs_truth"] else ""
        moving = f"{moving_error(j):.4f}" if moving_error(j) is not None else ""
        t = j.get("temporal") or {}
        ghost = f"{t['ghosting_error']:.4f}" if t.get("disoccluded_pixels") else ""
        out.append(f"| {label} | {f['median']:.1f} [{f['q1']:.0f}..{f['q3']:.0f}] | "
                   f"{j['error_vs_truth']['rmse']:.4f} | {flip} | {moving} | {ghost} | {same_n} | "
                   f"{j['error_vs_truth']['ssim']:.3f} | "
                   f"{pct(j['mean_luminance'], j['truth']['mean_luminance'])} | "
                   f"{j['bytes_per_pixel']:.1f} | {ev['mean']:.2f} / {ev.get('worst_lane_mean', 0.0):.2f} |")
    return out


def passes_table(rows):
    out = ["| method | passes, median GPU ms (the frame's read-backs for the bench left out) |", "|---|---|"]
    for j in rows:
        parts = ", ".join(f"`{p['name']}` {p['gpu_ms']['median']:.1f}" for p in j["timing"]["passes"]
                          if not p["name"].startswith("readback."))
        out.append(f"| {method_label(j)} | {parts} |")
    return out


def page(run, jobs):
    data = headline_data(jobs)
    first = jobs[0]
    devices = sorted({j["timing"]["device"] for j in jobs})
    k = first["truth"]["supersampling"]
    g, m = run["git"], run["machine"]
    changed = g["uncommitted_changes"]
    state = ""
    if changed is True:  # recorded before the paths were listed
        state = "; the working tree also held uncommitted changes"
    elif changed:
        shown = ", ".join(f"`{c}`" for c in changed[:6])
        if len(changed) > 6:
            shown += f" and {len(changed) - 6} more"
        state = f"; the working tree also held uncommitted changes to {shown}"
    lines = [
        "# Measured results",
        "",
        "<!-- Written by tools/results-page.py from one recorded agaa-bench run. Do not edit by hand: -->",
        "<!-- tools/run.sh, then tools/results-page.py out/bench --write docs/results.md "
        "--readme README.md -->",
        "",
        wrap("Every figure on this page comes from one agaa-bench run. Errors are display RMSE "
             "(sRGB-encoded, tone-mapped) against the converged truth: the reference at n = 32 with "
             f"sample-rate shading, {k}x{k} supersampled ({first['truth']['samples'] * k * k} samples a "
             "pixel; [truth.md](truth.md)). Frame time is the median of the timed frames' GPU time, the "
             "sum of the frame's passes. lavapipe's times are a software rasteriser's and vary between "
             "runs on a shared machine: read them as ratios within a scene."),
        "",
        "## The run",
        "",
        "| | |",
        "|---|---|",
        f"| command | `{run['command']}` |",
        f"| started | {run['started_utc']} |",
        f"| wall time | {run['wall_s']:.0f} s |",
        f"| machine | {m['cpu']}, {m['cores']} cores; load average {m['load_at_start']:.2f} when the run "
        "started |",
        f"| device | {', '.join(devices)}; Mesa {m['mesa']} (lavapipe) |",
        f"| commit | {g['commit']}{state} |",
        f"| per job | {first['width']}x{first['height']}, {first['frames_warmup']} warm-up + "
        f"{first['frames_timed']} timed frames |",
        "",
        "## At the same frame time",
        "",
        wrap("Per scene, each method's error and frame time. The last rows name the method closest to "
             "the truth among those whose frame time is at most AGAA's slowest timed frame: still, moving "
             "along the camera path, and by FLIP, where the run measured them; where the next ones are within "
             f"{DECIDED_RATIO:g} times the truth's own error of it, the row says \"undecided\" and names them all. The "
             "README shows this table."),
        "",
        headline_block(data, run),
        "",
        "## Every job",
        "",
        wrap("\"vs reference at the same n\" is the shading error at fixed visibility; \"mean vs "
             "truth's\" the linear image mean (energy) against the truth's. \"moving: ghosting\" is the "
             "display RMSE along the camera path on the pixels the frame before did not see (a temporal "
             "method's history there is another surface's). Bytes per pixel are the "
             "method's own storage, from the real allocations."),
    ]
    for scene in scene_order(jobs):
        rows = sorted((j for j in jobs if j["scene"] == scene), key=method_rank)
        lines += ["", f"### {scene}", "",
                  f"Truth's own error {rows[0]['truth']['error_estimate']:.4f}.", ""]
        lines += job_table(rows)
        lines += ["", "<details><summary>per pass</summary>", ""]
        lines += passes_table(rows)
        lines += ["", "</details>"]
    # One line for the run and one per scene: small, and a rerun's diff reads scene by scene.
    scenes_json = ",\n  ".join(json.dumps(s, sort_keys=True) for s in data)
    data_json = f'{{"run": {json.dumps(run, sort_keys=True)},\n "headline": [\n  {scenes_json}\n ]}}'

    lines += ["", DATA_BEGIN, data_json, DATA_END, ""]
    return "\n".join(lines)


# ---- blocks and the check -----------------------------------------------------------------

def block(text, where):
    b, e = text.find(BEGIN), text.find(END)
    if b < 0 or e < b or text.count(BEGIN) != 1 or text.count(END) != 1:
        raise Refused(f"{where}: needs exactly one '{BEGIN}' followed by one '{END}'")
    return text[b:e + len(END)]


def page_data(text, where):
    b = text.rfind(DATA_BEGIN)
    e = text.find(DATA_END, b + len(DATA_BEGIN))
    if b < 0 or e < 0:
        raise Refused(f"{where}: no '{DATA_BEGIN} ... {DATA_END}' block (write the page with this script)")
    try:
        return json.loads(text[b + len(DATA_BEGIN):e])
    except json.JSONDecodeError as err:
        raise Refused(f"{where}: the data block is not JSON ({err})")


def first_difference(a, b, name_a, name_b):
    la, lb = a.splitlines(), b.splitlines()
    for i in range(max(len(la), len(lb))):
        x = la[i] if i < len(la) else "(nothing)"
        y = lb[i] if i < len(lb) else "(nothing)"
        if x != y:
            return f"line {i + 1} of the block:\n  {name_a}: {x}\n  {name_b}: {y}"
    return ""


def check(page_file, readme_file):
    with open(page_file) as f:
        page_text = f.read()
    with open(readme_file) as f:
        readme_text = f.read()
    data = page_data(page_text, page_file)
    implied = headline_block(data["headline"], data["run"])
    in_page = block(page_text, page_file)
    in_readme = block(readme_text, readme_file)
    problems = []
    if in_page != implied:
        problems.append(f"{page_file}'s headline table is not the one its data implies (edited by hand?); "
                        + first_difference(in_page, implied, page_file, "its data"))
    if in_readme != implied:
        problems.append(f"{readme_file}'s headline table differs from {page_file}'s; "
                        + first_difference(in_readme, implied, readme_file, f"{page_file} (from its data)"))
    if problems:
        raise Refused("\n".join(problems) + "\nregenerate both from the recorded run: tools/results-page.py "
                      "out/bench --write docs/results.md --readme README.md")
    print(f"results-page: {readme_file}'s headline table is {page_file}'s, and its data's")


def write(out_dir, page_file, readme_file):
    run, jobs = load_run(out_dir)
    text = page(run, jobs)
    with open(page_file, "w") as f:
        f.write(text)
    print(f"results-page: wrote {page_file} ({len(jobs)} jobs)")
    if readme_file:
        with open(readme_file) as f:
            readme = f.read()
        old = block(readme, readme_file)
        new = block(text, page_file)
        with open(readme_file, "w") as f:
            f.write(readme.replace(old, new))
        print(f"results-page: {'rewrote' if old != new else 'kept'} the headline table in {readme_file}")


def main(argv):
    command = []
    if "--" in argv:
        i = argv.index("--")
        argv, command = argv[:i], argv[i + 1:]
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    p.add_argument("dir", nargs="?", help="the bench's output folder (agaa-bench --out DIR)")
    p.add_argument("--record", metavar="DIR", help="run the command after -- and record it in DIR/run.json")
    p.add_argument("--write", metavar="FILE", help="write the results page to FILE")
    p.add_argument("--readme", metavar="FILE", help="the README whose headline block to rewrite or check")
    p.add_argument("--check", action="store_true", help="check the README's headline table against the page")
    p.add_argument("--page", metavar="FILE", default=os.path.join(ROOT, "docs", "results.md"),
                   help="the results page --check reads (default docs/results.md)")
    a = p.parse_args(argv)
    try:
        if a.record:
            return record(a.record, command)
        if a.check:
            check(a.page, a.readme or os.path.join(ROOT, "README.md"))
            return 0
        if not a.dir or not a.write:
            p.error("give DIR --write FILE, --check, or --record DIR -- COMMAND")
        write(a.dir, a.write, a.readme)
        return 0
    except Refused as e:
        print(f"results-page: {e}", file=sys.stderr)
        return 1
    except OSError as e:  # a file named on the command line that cannot be read or written
        print(f"results-page: {e}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
