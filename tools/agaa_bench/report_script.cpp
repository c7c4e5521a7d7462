#include "report_script.h"

namespace agaa::bench {

const char* reportScript() {
    return R"JS(
"use strict";
(function () {
  const palette = ["#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b", "#e377c2", "#17becf",
                   "#7f7f7f", "#bcbd22"];
  const methodColour = (m) => palette[Math.max(0, BENCH.methods.indexOf(m)) % palette.length];
  const groupColour = (g) => palette[(BENCH.passGroups.indexOf(g) + 3) % palette.length];
  const chartErrors = [];
  let charts = 0;
  let knobCurves = 0; // AGAA's knob curves drawn (document.body.dataset.knobCurves)

  // Draws each point's label beside it (Chart.js 3 has no built-in data labels).
  const pointLabels = {
    id: "pointLabels",
    afterDatasetsDraw(chart) {
      const ctx = chart.ctx;
      ctx.save();
      ctx.font = "10px sans-serif";
      ctx.fillStyle = "#333";
      chart.data.datasets.forEach((ds, i) => {
        if (!ds.pointLabels || !chart.isDatasetVisible(i)) return;
        chart.getDatasetMeta(i).data.forEach((pt, k) => ctx.fillText(ds.pointLabels[k], pt.x + 5, pt.y - 5));
      });
      ctx.restore();
    },
  };
  // Whiskers around each point: ds.xSpread holds the min..max of the timed frames behind its
  // median frame time, ds.ySpread the truth's own error around its measured error (null: unknown).
  const spreads = {
    id: "spreads",
    afterDatasetsDraw(chart) {
      const ctx = chart.ctx, x = chart.scales.x, y = chart.scales.y;
      // A line from a to b with 3-pixel end ticks across it.
      function whisker(a, b, horizontal) {
        const t = horizontal ? [0, 3] : [3, 0];
        ctx.beginPath();
        ctx.moveTo(a[0], a[1]);
        ctx.lineTo(b[0], b[1]);
        for (const e of [a, b]) {
          ctx.moveTo(e[0] - t[0], e[1] - t[1]);
          ctx.lineTo(e[0] + t[0], e[1] + t[1]);
        }
        ctx.stroke();
      }
      ctx.save();
      chart.data.datasets.forEach((ds, i) => {
        if (!chart.isDatasetVisible(i)) return;
        ctx.strokeStyle = ds.borderColor;
        chart.getDatasetMeta(i).data.forEach((pt, k) => {
          if (ds.xSpread) {
            const [lo, hi] = ds.xSpread[k];
            whisker([x.getPixelForValue(lo), pt.y], [x.getPixelForValue(hi), pt.y], true);
          }
          if (ds.ySpread && ds.ySpread[k] !== null) {
            const [lo, hi] = ds.ySpread[k];
            whisker([pt.x, y.getPixelForValue(Math.max(0, lo))], [pt.x, y.getPixelForValue(hi)], false);
          }
        });
      });
      ctx.restore();
    },
  };

  // Points not dominated by another (lower or equal cost and lower or equal error), by cost.
  function paretoFront(points) {
    const sorted = points.slice().sort((a, b) => a.x - b.x || a.y - b.y);
    const front = [];
    let best = Infinity;
    for (const p of sorted) {
      if (p.y < best) {
        front.push(p);
        best = p.y;
      }
    }
    return front;
  }

  function tradeOffChart(canvas, jobs, xKey, xTitle) {
    const withError = jobs.filter((j) => j.rmse !== null);
    const datasets = [];
    for (const m of BENCH.methods) {
      const js = withError.filter((j) => j.method === m);
      if (!js.length) continue;
      const ds = {
        type: "scatter",
        label: m,
        data: js.map((j) => ({ x: j[xKey], y: j.rmse })),
        pointLabels: js.map((j) => j.setting || j.method), // single-setting methods by name
        backgroundColor: methodColour(m),
        borderColor: methodColour(m),
        pointRadius: 4,
      };
      if (xKey === "frameMs") ds.xSpread = js.map((j) => [j.frameMin, j.frameMax]);
      ds.ySpread = js.map((j) => (j.rmseBar === null ? null : [j.rmse - j.rmseBar, j.rmse + j.rmseBar]));
      datasets.push(ds);
    }
    // AGAA's knob (issue 35): each (method, n, c) run at two or more tolerances (the default, never,
    // T) as one curve through its settings in order of cost, so what each step of the knob buys
    // reads along it.
    const knobs = new Map();
    for (const j of withError) {
      if (!j.knob) continue;
      if (!knobs.has(j.knob)) knobs.set(j.knob, []);
      knobs.get(j.knob).push(j);
    }
    for (const [knob, js] of knobs) {
      if (js.length < 2) continue;
      js.sort((a, b) => a[xKey] - b[xKey]);
      knobCurves++;
      datasets.push({
        type: "line",
        label: knob + " knob",
        data: js.map((j) => ({ x: j[xKey], y: j.rmse })),
        borderColor: methodColour(js[0].method),
        borderWidth: 1.5,
        pointRadius: 0,
        fill: false,
      });
    }
    datasets.push({
      type: "line",
      label: "Pareto front",
      data: paretoFront(withError.map((j) => ({ x: j[xKey], y: j.rmse }))),
      borderColor: "#444",
      borderDash: [6, 4],
      borderWidth: 1.5,
      pointRadius: 0,
      fill: false,
    });
    return new Chart(canvas, {
      data: { datasets },
      plugins: [pointLabels, spreads],
      options: {
        animation: false,
        layout: { padding: { right: 40, top: 8 } }, // room for the labels of the outermost points
        responsive: true,
        maintainAspectRatio: false,
        scales: {
          x: { type: "linear", beginAtZero: true, title: { display: true, text: xTitle } },
          y: { beginAtZero: true, title: { display: true, text: "RMSE vs truth (sRGB); bars: the truth's own error" } },
        },
        plugins: { legend: { position: "bottom" } },
      },
    });
  }

  function passChart(canvas, jobs) {
    const groups = BENCH.passGroups.filter((g) => jobs.some((j) => j.passes[g] !== undefined));
    return new Chart(canvas, {
      type: "bar",
      data: {
        labels: jobs.map((j) => j.label),
        datasets: groups.map((g) => ({
          label: g,
          data: jobs.map((j) => j.passes[g] ?? 0),
          backgroundColor: groupColour(g),
        })),
      },
      options: {
        animation: false,
        responsive: true,
        maintainAspectRatio: false,
        scales: {
          x: { stacked: true, ticks: { autoSkip: false, maxRotation: 60, minRotation: 30 } },
          y: { stacked: true, beginAtZero: true, title: { display: true, text: "GPU ms (median per pass)" } },
        },
        plugins: { legend: { position: "bottom" } },
      },
    });
  }

  function growthChart(canvas, jobs, yKey, yTitle) {
    const sampled = jobs.filter((j) => j.usesSamples);
    const ns = [...new Set(sampled.map((j) => j.n))].sort((a, b) => a - b);
    const series = [...new Set(sampled.map((j) => j.series))];
    return new Chart(canvas, {
      type: "line",
      data: {
        labels: ns.map((n) => n + "x"),
        datasets: series.map((s) => {
          const js = sampled.filter((j) => j.series === s);
          return {
            label: s,
            data: ns.map((n) => {
              const j = js.find((k) => k.n === n);
              return j ? j[yKey] : null;
            }),
            borderColor: methodColour(js[0].method),
            backgroundColor: methodColour(js[0].method),
            borderDash: js[0].c > 1 ? [4 * (js[0].c - 1), 3] : [],
            spanGaps: true,
          };
        }),
      },
      options: {
        animation: false,
        responsive: true,
        maintainAspectRatio: false,
        scales: {
          x: { title: { display: true, text: "visibility samples per pixel (n)" } },
          y: { beginAtZero: true, title: { display: true, text: yTitle } },
        },
        plugins: { legend: { position: "bottom" } },
      },
    });
  }

  const canvases = document.querySelectorAll("canvas[data-chart]");
  for (const canvas of canvases) {
    const jobs = BENCH.jobs.filter((j) => j.scene === canvas.dataset.scene);
    try {
      const kind = canvas.dataset.chart;
      if (kind === "time") tradeOffChart(canvas, jobs, "frameMs", "frame GPU ms (median; whiskers min..max)");
      else if (kind === "memory") tradeOffChart(canvas, jobs, "bpp", "bytes per pixel (technique storage)");
      else if (kind === "passes") passChart(canvas, jobs);
      else if (kind === "growth-time") growthChart(canvas, jobs, "frameMs", "frame GPU ms (median)");
      else if (kind === "growth-memory") growthChart(canvas, jobs, "bpp", "bytes per pixel");
      else throw new Error("unknown chart kind " + kind);
      charts++;
    } catch (e) {
      chartErrors.push(canvas.dataset.scene + "/" + canvas.dataset.chart + ": " + e.message);
    }
  }

  // Image comparison: the slider uncovers the method's crop over the truth's.
  for (const slider of document.querySelectorAll("input.cmp-slider")) {
    const top = slider.parentElement.querySelector(".cmp-top");
    const apply = () => (top.style.clipPath = "inset(0 " + (100 - slider.value) + "% 0 0)");
    slider.addEventListener("input", apply);
    apply();
  }
  for (const button of document.querySelectorAll("button.cmp-toggle")) {
    button.addEventListener("click", () => {
      const table = document.getElementById(button.dataset.table);
      const showHeat = table.classList.toggle("show-heat");
      button.textContent = showHeat ? "slider: error heatmap over truth" : "slider: method over truth";
    });
  }

  window.addEventListener("load", () => {
    const images = [...document.images];
    const broken = images.filter((i) => !(i.complete && i.naturalWidth > 0));
    let state;
    if (chartErrors.length || charts !== canvases.length)
      state = "error:charts:" + charts + "/" + canvases.length + ":" + chartErrors.join(";");
    else if (broken.length) state = "error:images:" + broken.map((i) => i.getAttribute("src")).join(";");
    else state = "ok:" + charts + ":" + images.length;
    document.body.dataset.rendered = state;
    document.body.dataset.knobCurves = String(knobCurves);
  });
})();
)JS";
}

} // namespace agaa::bench
