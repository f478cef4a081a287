// pqhull viewer: draws scenes (triangles, points, segments, labels) on canvases, one panel per
// sequence of frames, with a step slider per panel; 3-D panels rotate with the mouse (one view
// shared by every panel, so that side-by-side runs are seen from the same side). A panel's frames
// are given (generic scenes) or built here from a recorded pqhull trace by replaying its events.
// Inlined into the page by src/viz/scene.rs: no network, no library.
"use strict";
(function () {
  const root = document.documentElement;
  const DATA = JSON.parse(document.getElementById("pqhull-data").textContent);
  const view = { yaw: -0.65, pitch: 0.42, zoom: 1 };
  const LIGHT = normalize([0.35, 0.5, 1]);
  const COLORS = {
    facet: [165, 195, 230, 0.6], chosen: [255, 140, 0, 0.95], created: [70, 185, 95, 0.92],
    stop: [215, 45, 60, 0.95], removed: [200, 40, 40, 0.9], fill: [226, 236, 247, 1],
    vertex: [30, 60, 120, 1], outside: [220, 50, 50, 1], chosenOutside: [255, 120, 0, 1],
    inside: [165, 165, 165, 1], added: [0, 150, 60, 1], query: [130, 0, 170, 1],
    mark: [0, 0, 0, 1], ray: [0, 140, 140, 0.85], text: [20, 20, 20, 1],
  };

  function normalize(v) { const n = Math.hypot(v[0], v[1], v[2]) || 1; return [v[0] / n, v[1] / n, v[2] / n]; }
  function to3(p) { return [p[0], p[1], p.length > 2 ? p[2] : 0]; }
  function rgba(c, k) {
    const f = k === undefined ? 1 : k;
    return "rgba(" + Math.round(c[0] * f) + "," + Math.round(c[1] * f) + "," + Math.round(c[2] * f) + "," + c[3] + ")";
  }
  function fmt(v) { return v === null || v === undefined ? "non-finite" : Number(v).toPrecision(6); }

  // ---- a recorded trace, replayed on demand -------------------------------------------------
  function TraceModel(t) {
    this.t = t;
    this.steps = t.events.length;
    this.dimension = t.dimension;
    this.ows = t.disturbances.length > 0;
    this.reset();
  }
  TraceModel.prototype.reset = function () {
    this.facets = new Map(); this.pos = 0; this.mark = null; this.factor = null;
    this.seen = new Map(); // serial -> vertices, for drawing removed facets
    // Points an implicit source inserts later are not drawn before they exist.
    this.pending = new Set(this.t.events.filter((e) => e.kind === "inserted").map((e) => e.point));
  };
  TraceModel.prototype.remember = function (f) { this.facets.set(f.serial, { v: f.vertices, out: f.outside.slice() }); this.seen.set(f.serial, f.vertices); };
  TraceModel.prototype.apply = function (e) {
    if (e.kind === "initial") { this.facets = new Map(); e.facets.forEach((f) => this.remember(f)); }
    else if (e.kind === "claimed") {
      const moved = new Set(e.points);
      this.facets.forEach((f, s) => { if (s !== e.facet) f.out = f.out.filter((p) => !moved.has(p)); });
      const f = this.facets.get(e.facet); if (f) f.out = f.out.concat(e.points);
    } else if (e.kind === "expanded") {
      e.removed.forEach((s) => this.facets.delete(s));
      e.created.forEach((f) => this.remember(f));
    } else if (e.kind === "inserted") { this.pending.delete(e.point); }
    else if (e.kind === "note" && e.point) { this.mark = e.point; }
    else if (e.kind === "chose" && e.key && e.key.name === "inflation factor" && e.key.value !== null) { this.factor = e.key.value; }
  };
  TraceModel.prototype.seek = function (k) {
    if (this.pos > k + 1) this.reset();
    while (this.pos <= k) this.apply(this.t.events[this.pos++]);
  };
  TraceModel.prototype.bounds = function () {
    const pts = this.t.points.map(to3);
    if (this.t.query) pts.push(to3(this.t.query));
    if (this.ows) pts.push([0, 0, 0]);
    return pts;
  };
  TraceModel.prototype.describe = function (e) {
    switch (e.kind) {
      case "initial": return "initial simplex: " + e.facets.length + " facets";
      case "chose": return "chose facet #" + e.facet + " (vertices " + e.vertices.join(" ") + "): " + e.reason +
        (e.key ? "; " + e.key.name + " = " + fmt(e.key.value) : "");
      case "claimed": return "facet #" + e.facet + " claimed " + e.points.length + " point(s) lying beyond it from other outside sets";
      case "inserted": return "implicit point " + e.point + " = (" + e.coordinates.map(fmt).join(", ") + ") inserted beyond facet #" + e.facet;
      case "expanded": return "added point " + e.point + " beyond facet #" + e.facet + ": removed " + e.removed.length +
        " facet(s), created " + e.created.length;
      case "note": return e.text;
      case "stop": return "stop: " + e.reason;
      default: return e.kind;
    }
  };
  TraceModel.prototype.frame = function (k, radius) {
    this.seek(k);
    const e = this.t.events[k], P = this.t.points, two = this.dimension === 2;
    const scene = { caption: "", triangles: [], points: [], segments: [], labels: [] };
    const focus = e.kind === "chose" || e.kind === "claimed" || e.kind === "inserted" ? e.facet : null;
    const created = new Set(e.kind === "expanded" ? e.created.map((f) => f.serial) : []);
    const stop = e.kind === "stop" ? e.facet : null;
    const isVertex = new Set(), outside = new Set(), focusOutside = new Set();
    let centre = [0, 0, 0], count = 0;
    this.facets.forEach((f) => f.v.forEach((v) => isVertex.add(v)));
    isVertex.forEach((v) => { const p = to3(P[v]); centre = [centre[0] + p[0], centre[1] + p[1], centre[2] + p[2]]; count++; });
    centre = centre.map((c) => c / Math.max(count, 1));
    this.facets.forEach((f, s) => {
      f.out.forEach((p) => { outside.add(p); if (s === focus) focusOutside.add(p); });
      const colour = s === focus ? COLORS.chosen : s === stop ? COLORS.stop : created.has(s) ? COLORS.created : COLORS.facet;
      const c = f.v.map((v) => to3(P[v]));
      if (two) {
        scene.triangles.push({ c: [centre, c[0], c[1]], color: COLORS.fill });
        scene.segments.push({ a: c[0], b: c[1], color: colour, width: colour === COLORS.facet ? 2 : 4.5 });
      } else {
        scene.triangles.push({ c: c, color: colour });
      }
    });
    if (e.kind === "expanded") {
      e.removed.forEach((s) => {
        const v = this.seen.get(s); if (!v) return;
        for (let i = 0; i < v.length; i++) {
          for (let j = i + 1; j < v.length; j++) {
            scene.segments.push({ a: to3(P[v[i]]), b: to3(P[v[j]]), color: COLORS.removed, width: 1.5, dash: true });
          }
        }
      });
    }
    const added = e.kind === "expanded" || e.kind === "inserted" ? e.point : null;
    for (let i = 0; i < P.length; i++) {
      if (this.pending.has(i)) continue;
      let color = COLORS.inside, r = 2.5;
      if (i === added) { color = COLORS.added; r = 6.5; }
      else if (focusOutside.has(i)) { color = COLORS.chosenOutside; r = 4.5; }
      else if (outside.has(i)) { color = COLORS.outside; r = 3.5; }
      else if (isVertex.has(i)) { color = COLORS.vertex; r = 3.5; }
      scene.points.push({ p: to3(P[i]), color: color, r: r });
    }
    if (added !== null) scene.labels.push({ p: to3(P[added]), text: "p" + added, color: COLORS.added });
    if (this.t.query) {
      const q = to3(this.t.query);
      scene.points.push({ p: q, color: COLORS.query, r: 6, top: true });
      scene.labels.push({ p: q, text: "q", color: COLORS.query });
      if (this.mark) scene.segments.push({ a: q, b: to3(this.mark), color: COLORS.query, width: 1.5, dash: true });
    }
    if (this.mark) {
      scene.points.push({ p: to3(this.mark), color: COLORS.mark, r: 5, top: true });
      scene.labels.push({ p: to3(this.mark), text: this.t.query ? "x" : "0", color: COLORS.mark });
    }
    if (this.ows) {
      const D = this.t.disturbances;
      const longest = Math.max.apply(null, D.map((d) => Math.hypot.apply(null, d))) || 1;
      const s = this.factor !== null ? this.factor : 0.6 * radius / longest;
      D.forEach((d, i) => {
        const end = to3(d.map((x) => -s * x));
        scene.segments.push({ a: [0, 0, 0], b: end, color: COLORS.ray, width: 1.5 });
        scene.points.push({ p: end, color: COLORS.ray, r: 3 });
        if (D.length <= 16) scene.labels.push({ p: end, text: "-" + (this.factor !== null ? "r" : "") + "d" + i, color: COLORS.ray });
      });
      if (!this.mark) scene.points.push({ p: [0, 0, 0], color: COLORS.mark, r: 4 });
    }
    scene.caption = this.describe(e);
    scene.status = this.facets.size + " facets, " + isVertex.size + " vertices, " + outside.size + " point(s) in outside sets" +
      (this.ows && this.factor !== null ? "; rays drawn at r = " + fmt(this.factor) : "");
    return scene;
  };

  // ---- generic frames (from Rust `Scene`s) ----------------------------------------------------
  function FramesModel(spec) {
    const palette = (f) => (i) => f.colors[i];
    this.frames = spec.frames.map((f) => {
      const c = palette(f);
      return {
        caption: f.caption, status: "",
        triangles: f.triangles.map((t) => ({ c: [t.slice(0, 3), t.slice(3, 6), t.slice(6, 9)], color: c(t[9]) })),
        points: f.points.map((p) => ({ p: p.slice(0, 3), color: c(p[3]), r: p[4] })),
        segments: f.segments.map((s) => ({ a: s.slice(0, 3), b: s.slice(3, 6), color: c(s[6]), width: s[7] })),
        labels: f.labels.map((l) => ({ p: l.slice(0, 3), text: l[3], color: c(l[4]) })),
      };
    });
    this.steps = this.frames.length;
    this.dimension = 3;
  }
  FramesModel.prototype.frame = function (k) { return this.frames[k]; };
  FramesModel.prototype.bounds = function () {
    const pts = [];
    this.frames.forEach((f) => {
      f.triangles.forEach((t) => t.c.forEach((p) => pts.push(p)));
      f.points.forEach((p) => pts.push(p.p));
      f.segments.forEach((s) => { pts.push(s.a); pts.push(s.b); });
    });
    return pts;
  };

  // ---- drawing ---------------------------------------------------------------------------------
  function box(points) {
    const lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
    points.forEach((p) => { for (let i = 0; i < 3; i++) { lo[i] = Math.min(lo[i], p[i]); hi[i] = Math.max(hi[i], p[i]); } });
    if (!points.length) return { centre: [0, 0, 0], radius: 1 };
    const centre = [0, 1, 2].map((i) => 0.5 * (lo[i] + hi[i]));
    // The farthest point from the centre: the picture fits the canvas at every rotation.
    let radius = 0;
    points.forEach((p) => { radius = Math.max(radius, Math.hypot(p[0] - centre[0], p[1] - centre[1], p[2] - centre[2])); });
    return { centre: centre, radius: Math.max(radius, 1e-12) };
  }
  function projector(panel, W, H) {
    const b = panel.box, two = panel.model.dimension === 2;
    const cy = Math.cos(view.yaw), sy = Math.sin(view.yaw), cp = Math.cos(view.pitch), sp = Math.sin(view.pitch);
    const scale = (two ? 1 : view.zoom) * Math.min(W, H) / (2.15 * b.radius);
    return function (p) {
      const v = [p[0] - b.centre[0], p[1] - b.centre[1], p[2] - b.centre[2]];
      if (two) return [W / 2 + scale * v[0], H / 2 - scale * v[1], 0];
      const x1 = cy * v[0] - sy * v[1], y1 = sy * v[0] + cy * v[1], z1 = v[2];
      const X = x1, Y = cp * z1 + sp * y1, Z = -cp * y1 + sp * z1;
      return [W / 2 + scale * X, H / 2 - scale * Y, Z];
    };
  }
  function draw(panel) {
    const canvas = panel.canvas, ctx = canvas.getContext("2d");
    const W = canvas.width, H = canvas.height;
    const frame = panel.model.frame(panel.step, panel.box.radius);
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.fillStyle = "#ffffff";
    ctx.fillRect(0, 0, W, H);
    const proj = projector(panel, W, H), eps = 0.02 * panel.box.radius, items = [];
    frame.triangles.forEach((t) => {
      const q = t.c.map(proj);
      let k = 1;
      if (panel.model.dimension !== 2) {
        const u = [q[1][0] - q[0][0], q[1][1] - q[0][1], q[1][2] - q[0][2]];
        const w = [q[2][0] - q[0][0], q[2][1] - q[0][1], q[2][2] - q[0][2]];
        // Screen y points down: flip it for a right-handed normal; shade both sides alike.
        const n = normalize([-(u[1] * w[2] - u[2] * w[1]), u[2] * w[0] - u[0] * w[2], -(u[0] * w[1] - u[1] * w[0])]);
        k = 0.45 + 0.55 * Math.abs(n[0] * LIGHT[0] + n[1] * LIGHT[1] + n[2] * LIGHT[2]);
      }
      items.push({ z: (q[0][2] + q[1][2] + q[2][2]) / 3, kind: 0, q: q, color: t.color, k: k });
    });
    frame.segments.forEach((s) => { const a = proj(s.a), b = proj(s.b); items.push({ z: 0.5 * (a[2] + b[2]) + eps / 2, kind: 1, a: a, b: b, s: s }); });
    // Query and marked points are what the run is about: always in front.
    frame.points.forEach((p) => { const a = proj(p.p); items.push({ z: p.top ? Infinity : a[2] + eps, kind: 2, a: a, p: p }); });
    items.sort((x, y) => x.z - y.z || x.kind - y.kind);
    ctx.lineJoin = "round";
    items.forEach((it) => {
      if (it.kind === 0) {
        ctx.beginPath(); ctx.moveTo(it.q[0][0], it.q[0][1]); ctx.lineTo(it.q[1][0], it.q[1][1]); ctx.lineTo(it.q[2][0], it.q[2][1]); ctx.closePath();
        ctx.fillStyle = rgba(it.color, it.k); ctx.fill();
        // 3-D: thin edges show the facets; 2-D: the fill's own colour hides the fan's seams.
        ctx.strokeStyle = panel.model.dimension !== 2 ? "rgba(40,60,90,0.35)" : rgba(it.color, it.k);
        ctx.lineWidth = panel.model.dimension !== 2 ? 0.7 : 1; ctx.stroke();
      } else if (it.kind === 1) {
        ctx.setLineDash(it.s.dash ? [5, 4] : []);
        ctx.beginPath(); ctx.moveTo(it.a[0], it.a[1]); ctx.lineTo(it.b[0], it.b[1]);
        ctx.strokeStyle = rgba(it.s.color); ctx.lineWidth = it.s.width; ctx.stroke();
        ctx.setLineDash([]);
      } else {
        ctx.beginPath(); ctx.arc(it.a[0], it.a[1], it.p.r, 0, 2 * Math.PI);
        ctx.fillStyle = rgba(it.p.color); ctx.fill();
        ctx.strokeStyle = "rgba(255,255,255,0.9)"; ctx.lineWidth = 1; ctx.stroke();
      }
    });
    ctx.font = "bold 13px sans-serif"; ctx.lineWidth = 3; ctx.strokeStyle = "rgba(255,255,255,0.9)";
    frame.labels.forEach((l) => {
      const a = proj(l.p);
      ctx.strokeText(l.text, a[0] + 7, a[1] - 7);
      ctx.fillStyle = rgba(l.color); ctx.fillText(l.text, a[0] + 7, a[1] - 7);
    });
    panel.caption.textContent = frame.caption;
    panel.status.textContent = frame.status || "";
    panel.counter.textContent = "step " + panel.step + " / " + (panel.model.steps - 1);
  }

  // ---- panels, controls, page state -------------------------------------------------------------
  const panels = [];
  function redrawAll() { panels.forEach(draw); publish(); }
  function publish() {
    root.setAttribute("data-steps", panels.map((p) => p.step).join(","));
    const c = panels.length ? panels[0].canvas.getBoundingClientRect() : null;
    if (c) root.setAttribute("data-canvas", [c.left, c.top, c.width, c.height].map(Math.round).join(","));
  }
  function setStep(panel, k) {
    panel.step = Math.max(0, Math.min(panel.model.steps - 1, k));
    panel.slider.value = String(panel.step);
    draw(panel); publish();
  }
  function element(tag, cls, parent, text) {
    const e = document.createElement(tag);
    if (cls) e.className = cls;
    if (text !== undefined) e.textContent = text;
    parent.appendChild(e);
    return e;
  }
  function makePanel(spec, host) {
    const div = element("div", "panel", host);
    element("h2", "", div, spec.title);
    const panel = { model: spec.trace ? new TraceModel(spec.trace) : new FramesModel(spec), step: 0 };
    panel.canvas = element("canvas", "", div);
    const controls = element("div", "controls", div);
    const prev = element("button", "", controls, "\u25c0");
    panel.slider = element("input", "", controls);
    panel.slider.type = "range"; panel.slider.min = "0"; panel.slider.max = String(panel.model.steps - 1); panel.slider.value = "0";
    const next = element("button", "", controls, "\u25b6");
    panel.counter = element("span", "counter", controls);
    panel.caption = element("p", "caption", div);
    panel.status = element("p", "status", div);
    panel.slider.disabled = panel.model.steps < 2;
    panel.slider.addEventListener("input", () => setStep(panel, Number(panel.slider.value)));
    prev.addEventListener("click", () => setStep(panel, panel.step - 1));
    next.addEventListener("click", () => setStep(panel, panel.step + 1));
    let drag = null;
    panel.canvas.addEventListener("pointerdown", (ev) => { drag = [ev.clientX, ev.clientY]; panel.canvas.setPointerCapture(ev.pointerId); });
    panel.canvas.addEventListener("pointerup", () => { drag = null; });
    panel.canvas.addEventListener("pointermove", (ev) => {
      if (!drag || panel.model.dimension === 2) return;
      view.yaw += 0.01 * (ev.clientX - drag[0]);
      view.pitch = Math.max(-1.55, Math.min(1.55, view.pitch + 0.01 * (ev.clientY - drag[1])));
      drag = [ev.clientX, ev.clientY];
      redrawAll();
    });
    panel.canvas.addEventListener("wheel", (ev) => {
      if (panel.model.dimension === 2) return;
      ev.preventDefault();
      view.zoom = Math.max(0.2, Math.min(20, view.zoom * Math.exp(-0.001 * ev.deltaY)));
      redrawAll();
    }, { passive: false });
    return panel;
  }
  function resize() {
    panels.forEach((p) => {
      const w = Math.max(200, Math.floor(p.canvas.clientWidth));
      const h = Math.max(220, Math.min(Math.floor(0.8 * w), window.innerHeight - 250));
      p.canvas.width = w; p.canvas.height = h;
    });
    redrawAll();
  }
  function fromHash() {
    const h = location.hash.replace(/^#/, "");
    const get = (name) => { const m = new RegExp("(?:^|&)" + name + "=([^&]*)").exec(h); return m ? decodeURIComponent(m[1]) : null; };
    const yaw = Number(get("yaw")), pitch = Number(get("pitch"));
    if (get("yaw") !== null && isFinite(yaw)) view.yaw = yaw;
    if (get("pitch") !== null && isFinite(pitch)) view.pitch = pitch;
    const steps = get("step");
    return steps === null ? [] : steps.split(",").map((s) => (s === "last" ? Infinity : Number(s)));
  }

  try {
    const host = document.getElementById("pqhull-panels");
    DATA.panels.forEach((spec) => panels.push(makePanel(spec, host)));
    const all = box([].concat.apply([], panels.map((p) => p.model.bounds())));
    panels.forEach((p) => { p.box = all; });
    resize();
    const steps = fromHash();
    panels.forEach((p, i) => {
      const wanted = steps.length ? steps[Math.min(i, steps.length - 1)] : p.model.steps - 1;
      // Through the slider, as a user would move it.
      p.slider.value = String(Math.max(0, Math.min(p.model.steps - 1, isFinite(wanted) ? wanted : p.model.steps - 1)));
      p.slider.dispatchEvent(new Event("input"));
    });
    window.addEventListener("resize", resize);
    window.addEventListener("hashchange", () => {
      const s = fromHash();
      panels.forEach((p, i) => { if (s.length) setStep(p, isFinite(s[Math.min(i, s.length - 1)]) ? s[Math.min(i, s.length - 1)] : p.model.steps - 1); });
      redrawAll();
    });
    document.addEventListener("keydown", (ev) => {
      const d = ev.key === "ArrowRight" ? 1 : ev.key === "ArrowLeft" ? -1 : 0;
      if (d && ev.target.tagName !== "INPUT") panels.forEach((p) => setStep(p, p.step + d));
    });
    root.setAttribute("data-ready", "1");
  } catch (err) {
    window.pqhullRecordError(String(err && err.stack ? err.stack : err));
  }
})();
