// Report page logic (no libraries, works from file://): the difference viewer over float data
// shipped as base64 float16, the isometric voxel view, and a status element for the browser test.
(function () {
  "use strict";
  function halfToFloat(h) {
    const s = (h & 0x8000) ? -1 : 1, e = (h >> 10) & 0x1f, f = h & 0x3ff;
    if (e === 0) return s * Math.pow(2, -14) * (f / 1024);
    if (e === 31) return f ? NaN : s * Infinity;
    return s * Math.pow(2, e - 15) * (1 + f / 1024);
  }
  function decode(img) {
    const bin = atob(img.data), n = bin.length / 2, out = new Float32Array(n);
    for (let i = 0; i < n; i++) out[i] = halfToFloat(bin.charCodeAt(2 * i) | (bin.charCodeAt(2 * i + 1) << 8));
    return out;
  }
  const srgb = (c) => (c <= 0.0031308 ? 12.92 * c : 1.055 * Math.pow(c, 1 / 2.4) - 0.055);
  // Khronos PBR Neutral, as the PNG previews use (ref/io/image_preview.cpp; docs/report.md,
  // "Display transform"): on the whole colour, hue kept, highlights compressed toward white.
  function pbrNeutral(r, g, b) {
    const start = 0.76, desat = 0.15, d = 1 - start;
    const x = Math.min(r, g, b), off = x < 0.08 ? x - 6.25 * x * x : 0.04;
    let c = [r - off, g - off, b - off];
    const peak = Math.max(c[0], c[1], c[2]);
    if (peak < start) return c;
    const np = 1 - (d * d) / (peak + d - start);
    const w = 1 - 1 / (desat * (peak - np) + 1);
    return c.map((v) => Math.min(1, Math.max(0, (v * np) / peak * (1 - w) + np * w)));
  }
  function magma(t) {  // short magma-like ramp
    const k = [[0, 0, 4], [80, 18, 123], [183, 55, 121], [252, 137, 97], [252, 253, 191]];
    t = Math.min(1, Math.max(0, t)) * (k.length - 1);
    const i = Math.min(k.length - 2, Math.floor(t)), f = t - i;
    return k[i].map((v, j) => v + (k[i + 1][j] - v) * f);
  }
  const status = { images: 0, loaded: 0, broken: [], viewer: "none", voxels: "none" };
  function report() {
    const el = document.getElementById("status");
    if (!el) return;
    el.textContent = JSON.stringify(status);
    el.setAttribute("data-ok", String(status.loaded === status.images && status.broken.length === 0 &&
      status.viewer !== "error" && status.voxels !== "error"));
  }

  function setupViewer() {
    const data = window.VCT_FLOAT_IMAGES || {};
    const names = Object.keys(data);
    const canvas = document.getElementById("viewer-canvas");
    if (!canvas) return;
    if (names.length === 0) { status.viewer = "no-data"; return; }
    const decoded = {};
    names.forEach((n) => (decoded[n] = decode(data[n])));
    const selA = document.getElementById("viewer-a"), selB = document.getElementById("viewer-b");
    const mode = document.getElementById("viewer-mode"), ev = document.getElementById("viewer-ev");
    const evOut = document.getElementById("viewer-ev-out"), info = document.getElementById("viewer-info");
    names.forEach((n, i) => {
      selA.add(new Option(n, n, i === 0, i === 0));
      selB.add(new Option(n, n, i === 1, i === 1));
    });
    let flipShowB = false;
    function draw() {
      const a = data[selA.value], b = data[selB.value] || a;
      const A = decoded[selA.value], B = decoded[selB.value] || A;
      canvas.width = a.w; canvas.height = a.h;
      const ctx = canvas.getContext("2d"), im = ctx.createImageData(a.w, a.h);
      const scale = Math.pow(2, parseFloat(ev.value));
      evOut.textContent = (parseFloat(ev.value) >= 0 ? "+" : "") + ev.value + " EV";
      const m = mode.value, sameSize = a.w === b.w && a.h === b.h;
      let sumDiff = 0;
      for (let p = 0; p < a.w * a.h; p++) {
        let rgb;
        if ((m === "diff" || m === "reldiff") && sameSize) {
          const la = 0.2126 * A[3 * p] + 0.7152 * A[3 * p + 1] + 0.0722 * A[3 * p + 2];
          const lb = 0.2126 * B[3 * p] + 0.7152 * B[3 * p + 1] + 0.0722 * B[3 * p + 2];
          let d = Math.abs(la - lb);
          sumDiff += d;
          if (m === "reldiff") d = d / (Math.abs(la) + 0.01);
          rgb = magma(d * scale);
        } else {
          const src = (m === "b" || (m === "flip" && flipShowB)) && sameSize ? B : A;
          const lin = [0, 1, 2].map((c) => (Number.isFinite(src[3 * p + c]) ? Math.max(0, src[3 * p + c] * scale) : 0));
          rgb = pbrNeutral(lin[0], lin[1], lin[2]).map((v) => 255 * srgb(Math.max(0, v)));
        }
        im.data[4 * p] = rgb[0]; im.data[4 * p + 1] = rgb[1]; im.data[4 * p + 2] = rgb[2]; im.data[4 * p + 3] = 255;
      }
      ctx.putImageData(im, 0, 0);
      const shown = m === "flip" ? (flipShowB ? selB.value : selA.value) : m === "b" ? selB.value : m === "a" ? selA.value : "|A-B|";
      info.textContent = "showing " + shown + (m.indexOf("diff") >= 0 ? " (mean |dL| = " + (sumDiff / (a.w * a.h)).toExponential(3) + ", heat scaled by exposure)" : "");
      canvas.setAttribute("data-drawn", shown);
    }
    [selA, selB, mode, ev].forEach((el) => el.addEventListener("input", draw));
    canvas.addEventListener("click", () => { flipShowB = !flipShowB; draw(); });
    setInterval(() => { if (mode.value === "flip") { flipShowB = !flipShowB; draw(); } }, 700);
    try {
      draw();
      // Self-check for the browser test: A and B views and the diff view must all render.
      const before = canvas.getAttribute("data-drawn");
      mode.value = "diff"; draw();
      const diffOk = canvas.getAttribute("data-drawn") === "|A-B|";
      // index.html#diff (or #flip, #reldiff, #b) opens the viewer in that mode: links and tests.
      const wanted = location.hash.replace("#", "");
      mode.value = ["a", "b", "flip", "diff", "reldiff"].indexOf(wanted) >= 0 ? wanted : "a";
      if (wanted === "diff" && names.length > 1) selB.value = names[names.length - 1];
      draw();
      status.viewer = diffOk && before ? "ok" : "error";
    } catch (e) { status.viewer = "error"; status.viewerError = String(e); }
  }

  function setupVoxels() {
    const v = window.VCT_VOXELS, canvas = document.getElementById("voxel-canvas");
    if (!canvas) return;
    if (!v || !v.points.length) { status.voxels = "no-data"; return; }
    const rot = document.getElementById("voxel-rot");
    function draw() {
      const ctx = canvas.getContext("2d"), W = canvas.width, H = canvas.height;
      ctx.fillStyle = "#111"; ctx.fillRect(0, 0, W, H);
      const a = parseFloat(rot.value) * Math.PI / 180, ca = Math.cos(a), sa = Math.sin(a), n = v.n;
      const pts = v.points.map((p) => {
        const x = p[0] / n - 0.5, y = p[1] / n - 0.5, z = p[2] / n - 0.5;
        const rx = ca * x + sa * z, rz = -sa * x + ca * z;  // turn about the vertical (y) axis
        return [rx, y, rz, p[3]];
      });
      pts.sort((p, q) => q[2] - p[2]);  // painter's order: far first
      const s = W * 0.62, size = Math.max(2, W / n * 0.9);
      for (const p of pts) {
        const sx = W / 2 + s * (p[0] + 0.35 * p[2]), sy = H / 2 - s * (p[1] - 0.25 * p[2]);
        ctx.fillStyle = "#" + p[3];
        ctx.fillRect(sx - size / 2, sy - size / 2, size, size);
      }
    }
    rot.addEventListener("input", draw);
    try { draw(); status.voxels = "ok"; } catch (e) { status.voxels = "error"; }
  }

  // The first screen's flip panel: alternates the two chosen final images (PNG previews) every
  // 700 ms while "flip" is ticked; a click flips by hand.
  function setupFlip() {
    const list = window.VCT_FLIP, img = document.getElementById("glance-flip-img");
    if (!list || !img) return;
    const pair = document.getElementById("glance-flip-pair"), auto = document.getElementById("glance-flip-auto");
    const shown = document.getElementById("glance-flip-shown");
    let second = false;
    function show() {
      const ij = pair.value.split(",").map(Number), k = ij[second ? 1 : 0];
      img.src = list[k][1];
      shown.textContent = list[k][0];
    }
    pair.addEventListener("input", () => { second = false; show(); });
    img.addEventListener("click", () => { auto.checked = false; second = !second; show(); });
    setInterval(() => { if (auto.checked) { second = !second; show(); } }, 700);
    show();
  }

  // For the browser test (docs/report.md): which first-screen elements lie wholly inside the
  // first viewport, i.e. are seen without scrolling.
  function checkGlance() {
    const ids = ["verdict-sentence", "glance-stage", "glance-mask", "glance-ref", "glance-gl", "glance-pt",
      "glance-flip", "glance-bias"];
    status.viewport = [window.innerWidth, window.innerHeight];
    status.glance = {};
    ids.forEach((id) => {
      const el = document.getElementById(id);
      if (!el) { status.glance[id] = "absent"; return; }
      const r = el.getBoundingClientRect();
      const inside = r.width > 0 && r.height > 0 && r.top >= 0 && r.left >= 0 &&
        r.bottom <= window.innerHeight + 0.5 && r.right <= window.innerWidth + 0.5;
      status.glance[id] = inside ? "in" : "out (" + [r.left, r.top, r.right, r.bottom].map(Math.round).join(",") + ")";
    });
    // At narrow widths the first screen re-flows instead of running off to the right.
    const g = document.getElementById("glance");
    status.glanceOverflow = g ? g.scrollWidth > g.clientWidth + 1 : false;
  }

  window.addEventListener("load", () => {
    const imgs = Array.from(document.images);
    status.images = imgs.length;
    imgs.forEach((im) => {
      if (im.complete && im.naturalWidth > 0) status.loaded++;
      else status.broken.push(im.getAttribute("src"));
    });
    setupViewer();
    setupVoxels();
    setupFlip();
    checkGlance();
    report();
  });
})();
