#pragma once
// The report page's script: builds every chart from the BENCH data the page
// carries, wires the image comparison sliders, and, once the page has loaded,
// sets document.body.dataset.rendered to "ok:<charts>:<images>" (or
// "error:..."), which the browser test reads.

namespace agaa::bench {

const char* reportScript();

} // namespace agaa::bench
