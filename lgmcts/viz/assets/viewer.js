/*
 * LGMCTS plan viewer: draws a tabletop scene to scale (SVG, seen from above,
 * the viewer at the bottom) and plays a rearrangement plan step by step.
 *
 *   var viewer = LGMCTSViewer.render(element, data);
 *
 * data = lgmcts.viz.viewer_data(...) (or the service's POST /view) = {
 *   scene: <scene JSON>, plan: <plan JSON with its goals>, instruction: str|null,
 *   footprints: {id: [[x, y], ...]}   object frame, metres
 *   paints: {id: {fill, second, mark, ink, edge, texture}}
 *   frames: [{poses: {id: [x, y, theta]}, on: {id: id|null}, goals: [<goal shape>, ...]}, ...]
 *           one per plan state, each the change over the state before: the
 *           objects whose pose or support changed and the goals drawn anew
 *           (a shape names its goal by `index`); the first frame lists every
 *           object and goal
 *   goal_text: [str, ...]   one line per goal
 * }
 * The script draws what it is given: replay, footprints, fits and goal
 * descriptions are computed once, in Python (see docs/viz.md).
 *
 * The returned controller has setStep(k), next(), prev(), play(), pause(),
 * toggle(), step(), count(), poses(), playing(), destroy(). The element
 * also gets it as element.lgmctsViewer. Self-contained: no network, no
 * libraries; the stylesheet is injected once into the document.
 */
(function (global) {
  "use strict";

  var SVGNS = "http://www.w3.org/2000/svg";
  var MM = 1000; // drawing units are millimetres
  var GOAL_COLORS = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#17becf", "#8c564b", "#e377c2"];
  var PURPOSE_COLORS = { goal: "#1b9e77", relocate: "#e8590c", unstack: "#7048e8" };
  var PURPOSE_WORDS = { goal: "place", relocate: "relocate", unstack: "unstack" };
  var CSS = [
    ".lgv{font:14px/1.4 system-ui,-apple-system,'Segoe UI',Roboto,Helvetica,Arial,sans-serif;color:#222;background:#fafaf7;padding:12px 16px;box-sizing:border-box;outline:none}",
    ".lgv *{box-sizing:border-box}",
    ".lgv-head h1{font-size:18px;margin:0 0 2px 0}",
    ".lgv-instr{font-style:italic;color:#444;margin:0 0 8px 0}",
    ".lgv-instr:empty{display:none}",
    ".lgv-body{display:flex;gap:16px;align-items:flex-start;flex-wrap:wrap}",
    ".lgv-stage{flex:1 1 560px;min-width:320px;background:#fff;border:1px solid #e3e0d8;border-radius:6px;padding:4px}",
    ".lgv-stage svg{width:100%;height:auto;display:block}",
    ".lgv-side{flex:0 1 340px;min-width:260px}",
    ".lgv-controls{display:flex;align-items:center;gap:6px;flex-wrap:wrap;margin-bottom:6px}",
    ".lgv-controls button{font:inherit;padding:3px 10px;border:1px solid #bbb;border-radius:4px;background:#fff;cursor:pointer}",
    ".lgv-controls button:hover{background:#f0efe9}",
    ".lgv-controls input[type=range]{flex:1 1 120px}",
    ".lgv-stepno{font-variant-numeric:tabular-nums;min-width:5.5em;text-align:right;color:#555}",
    ".lgv-caption{min-height:2.6em;padding:4px 8px;border-left:4px solid #ccc;background:#fff;margin-bottom:8px}",
    ".lgv h3{font-size:13px;text-transform:uppercase;letter-spacing:.04em;color:#666;margin:10px 0 4px}",
    ".lgv ul,.lgv ol{margin:0;padding:0;list-style:none}",
    ".lgv-goals li{display:flex;gap:6px;align-items:center;padding:2px 4px;border-radius:4px;cursor:default}",
    ".lgv-goals li:hover{background:#eef}",
    ".lgv-swatch{width:12px;height:12px;border-radius:2px;flex:none}",
    ".lgv-status{width:1.2em;text-align:center;font-weight:bold}",
    ".lgv-met .lgv-status{color:#1b9e77}.lgv-unmet .lgv-status{color:#c92a2a}",
    ".lgv-actions{max-height:320px;overflow:auto;border:1px solid #e3e0d8;border-radius:4px;background:#fff}",
    ".lgv-actions li{padding:3px 8px;cursor:pointer;border-left:4px solid transparent;font-variant-numeric:tabular-nums}",
    ".lgv-actions li:hover{background:#f3f3ee}",
    ".lgv-actions li.lgv-future{color:#999}",
    ".lgv-actions li.lgv-current{font-weight:600;background:#eef7f3}",
    ".lgv-legend{margin-top:10px;font-size:12px;color:#555;display:grid;grid-template-columns:auto 1fr;gap:2px 8px;align-items:center}",
    ".lgv-legend svg{width:34px;height:14px}",
    ".lgv-error{color:#b00020;font-weight:600;padding:8px}",
    ".lgv-obj.lgv-hl .lgv-outline{stroke:#000;stroke-width:6}",
    ".lgv text{font-family:system-ui,-apple-system,'Segoe UI',Roboto,Helvetica,Arial,sans-serif}"
  ].join("\n");

  // ------------------------------------------------------------ helpers

  function el(doc, tag, attrs, parent) {
    var e = doc.createElementNS(SVGNS, tag);
    for (var k in attrs) if (Object.prototype.hasOwnProperty.call(attrs, k)) e.setAttribute(k, attrs[k]);
    if (parent) parent.appendChild(e);
    return e;
  }

  function html(doc, tag, cls, parent, text) {
    var e = doc.createElement(tag);
    if (cls) e.className = cls;
    if (text !== undefined && text !== null) e.textContent = text;
    if (parent) parent.appendChild(e);
    return e;
  }

  function X(x) { return x * MM; }
  function Y(y) { return -y * MM; }
  function fmt(v) { return (Math.round(v * 100) / 100).toFixed(2); }
  function sign(v) { return (v >= 0 ? "+" : "") + fmt(v); }

  function pointsAttr(pts) {
    return pts.map(function (p) { return X(p[0]).toFixed(2) + "," + Y(p[1]).toFixed(2); }).join(" ");
  }

  function transform(local, pose) {
    var c = Math.cos(pose[2]), s = Math.sin(pose[2]);
    return local.map(function (p) { return [c * p[0] - s * p[1] + pose[0], s * p[0] + c * p[1] + pose[1]]; });
  }

  function checkData(data) {
    if (!data || typeof data !== "object") throw new Error("viewer data must be an object with 'scene' and 'plan'");
    if (!data.scene || !Array.isArray(data.scene.objects)) throw new Error("viewer data needs scene.objects");
    if (!data.scene.workspace || !data.scene.workspace.x || !data.scene.workspace.y) throw new Error("viewer data needs scene.workspace");
    if (!data.plan || !Array.isArray(data.plan.actions)) throw new Error("viewer data needs plan.actions");
    var ids = {};
    data.scene.objects.forEach(function (o) { ids[o.id] = true; });
    data.plan.actions.forEach(function (a, k) {
      if (!ids[a.object]) throw new Error("action " + (k + 1) + " moves unknown object " + a.object);
      if (a.on !== null && a.on !== undefined && !ids[a.on]) throw new Error("action " + (k + 1) + " places on unknown object " + a.on);
    });
    var computed = " (build the data with lgmcts.viz.viewer_data or the service's POST /view)";
    ["footprints", "paints"].forEach(function (key) {
      data.scene.objects.forEach(function (o) {
        if (!data[key] || !data[key][o.id]) throw new Error("viewer data lacks " + key + " of object " + o.id + computed);
      });
    });
    if (!Array.isArray(data.frames) || data.frames.length !== data.plan.actions.length + 1 ||
        !data.frames.every(function (f) { return f && f.poses && f.on && Array.isArray(f.goals); })) {
      throw new Error("viewer data needs one frame (poses, on, goals) per plan state" + computed);
    }
    data.scene.objects.forEach(function (o) {
      if (!data.frames[0].poses[o.id] || data.frames[0].on[o.id] === undefined) {
        throw new Error("the first frame lacks object " + o.id + computed);
      }
    });
  }

  function injectStyle(doc) {
    if (doc.getElementById("lgv-style")) return;
    var st = doc.createElement("style");
    st.id = "lgv-style";
    st.textContent = CSS;
    (doc.head || doc.documentElement).appendChild(st);
  }

  function texturePattern(doc, defs, id, paint) {
    if (!paint.texture) return null;
    var p = el(doc, "pattern", { id: id, patternUnits: "userSpaceOnUse", width: 10, height: 10 }, defs);
    var mk = paint.mark, t = paint.texture;
    if (t === "dots") el(doc, "circle", { cx: 5, cy: 5, r: 2.2, fill: mk }, p);
    else if (t === "checks") { el(doc, "rect", { x: 0, y: 0, width: 5, height: 5, fill: mk }, p); el(doc, "rect", { x: 5, y: 5, width: 5, height: 5, fill: mk }, p); }
    else if (t === "speckles") { el(doc, "circle", { cx: 2, cy: 3, r: 0.9, fill: mk }, p); el(doc, "circle", { cx: 7, cy: 8, r: 0.9, fill: mk }, p); el(doc, "circle", { cx: 8, cy: 2, r: 0.6, fill: mk }, p); }
    else if (t === "grain") { el(doc, "path", { d: "M0 2.5 H10 M0 7.5 H10", stroke: mk, "stroke-width": 1.2 }, p); }
    else if (t === "waves") { el(doc, "path", { d: "M0 5 Q2.5 1 5 5 T10 5", stroke: mk, "stroke-width": 1.3, fill: "none" }, p); }
    else { el(doc, "path", { d: "M-2 2 L2 -2 M0 10 L10 0 M8 12 L12 8", stroke: mk, "stroke-width": 2.2 }, p); }
    return "url(#" + id + ")";
  }

  var instances = 0;

  // ------------------------------------------------------------ render

  function render(container, data) {
    var doc = container.ownerDocument || document;
    injectStyle(doc);
    container.innerHTML = "";
    try {
      checkData(data);
    } catch (err) {
      html(doc, "div", "lgv-error", container, "Cannot show this plan: " + err.message);
      return null;
    }
    var uid = "lgv" + (++instances);
    var scene = data.scene, plan = data.plan, actions = plan.actions;
    var goals = (plan.goals && plan.goals.goals) || [];
    var n = actions.length;
    var objects = scene.objects.map(function (o) {
      return { id: o.id, name: o.name, color: o.color || "", local: data.footprints[o.id], paint: data.paints[o.id] };
    });
    var byId = {};
    objects.forEach(function (o) { byId[o.id] = o; });
    var frames = data.frames;
    // Each frame holds what changed since the one before: the state at step k
    // is built by applying frames 0..k, from the last state built when going on.
    var cursor = null;
    function frameAt(k) {
      if (cursor === null || k < cursor.k) cursor = { k: -1, poses: {}, on: {}, goals: [] };
      while (cursor.k < k) {
        cursor.k += 1;
        var f = frames[cursor.k], id;
        for (id in f.poses) cursor.poses[id] = f.poses[id];
        for (id in f.on) cursor.on[id] = f.on[id];
        f.goals.forEach(function (s) { cursor.goals[s.index] = s; });
      }
      return cursor;
    }
    // The pose each action's object had before it moved.
    var before = (function () {
      var poses = {}, out = [];
      for (var j = 0; j <= actions.length; j++) {
        for (var id in frames[j].poses) poses[id] = frames[j].poses[id];
        if (j < actions.length) out.push(poses[actions[j].object]);
      }
      return out;
    })();
    var goalText = data.goal_text || goals.map(function (g) { return g.pattern + " of " + g.objects.join(", "); });
    var member = {};
    goals.forEach(function (g, k) { g.objects.forEach(function (i) { (member[i] = member[i] || []).push(k); }); });

    // ---- layout
    var root = html(doc, "div", "lgv", container);
    root.tabIndex = 0;
    var head = html(doc, "div", "lgv-head", root);
    var solved = plan.solved ? "solved" : "not solved";
    html(doc, "h1", null, head, "Plan: " + n + " action" + (n === 1 ? "" : "s") + ", " + solved);
    html(doc, "p", "lgv-instr", head, data.instruction ? "\u201c" + data.instruction + "\u201d" : "");
    var body = html(doc, "div", "lgv-body", root);
    var stage = html(doc, "div", "lgv-stage", body);
    var side = html(doc, "div", "lgv-side", body);

    var controls = html(doc, "div", "lgv-controls", side);
    var bPrev = html(doc, "button", "lgv-prev", controls, "\u25C0");
    bPrev.title = "previous step (\u2190)";
    var bPlay = html(doc, "button", "lgv-play", controls, "\u25B6 Play");
    bPlay.title = "play / pause (space)";
    var bNext = html(doc, "button", "lgv-next", controls, "\u25B6\u2009");
    bNext.textContent = "\u25B6|";
    bNext.title = "next step (\u2192)";
    var slider = html(doc, "input", "lgv-slider", controls);
    slider.type = "range"; slider.min = 0; slider.max = n; slider.step = 1; slider.value = 0;
    slider.setAttribute("aria-label", "step");
    var stepNo = html(doc, "span", "lgv-stepno", controls, "");
    var caption = html(doc, "div", "lgv-caption", side, "");

    var goalList = null;
    if (goals.length) {
      html(doc, "h3", null, side, "Goals");
      goalList = html(doc, "ul", "lgv-goals", side);
    }
    html(doc, "h3", null, side, "Actions");
    var actList = html(doc, "ol", "lgv-actions", side);
    var startItem = html(doc, "li", "lgv-action", actList, "0. start");
    startItem.setAttribute("data-step", "0");
    var actItems = actions.map(function (a, k) {
      var o = byId[a.object];
      var where = a.on !== null && a.on !== undefined ? "onto " + a.on : "\u2192 (" + sign(a.to[0]) + ", " + sign(a.to[1]) + ")";
      var li = html(doc, "li", "lgv-action", actList, (k + 1) + ". " + PURPOSE_WORDS[a.purpose || "goal"] + " " + o.id + " " + o.name + " " + where);
      li.setAttribute("data-step", String(k + 1));
      li.style.borderLeftColor = PURPOSE_COLORS[a.purpose || "goal"];
      li.title = (a.purpose || "goal") + ": " + o.id + " " + (o.color ? o.color + " " : "") + o.name + " to (" + a.to.map(fmt).join(", ") + ")";
      return li;
    });
    var legend = html(doc, "div", "lgv-legend", side);
    [["goal placement", PURPOSE_COLORS.goal, "arrow"], ["relocation (obstacle)", PURPOSE_COLORS.relocate, "arrow"],
     ["unstack (blocker)", PURPOSE_COLORS.unstack, "arrow"], ["pose before the move", "#555", "dash"],
     ["goal shape, ring = goal object", GOAL_COLORS[0], "goal"], ["stacked object (shadow)", "#777", "stack"]].forEach(function (it) {
      var s = el(doc, "svg", { viewBox: "0 0 34 14" }, legend);
      if (it[2] === "arrow") { el(doc, "line", { x1: 2, y1: 7, x2: 26, y2: 7, stroke: it[1], "stroke-width": 3 }, s); el(doc, "path", { d: "M24 2 L33 7 L24 12 Z", fill: it[1] }, s); }
      else if (it[2] === "dash") el(doc, "rect", { x: 4, y: 2, width: 26, height: 10, fill: "none", stroke: it[1], "stroke-dasharray": "4 3" }, s);
      else if (it[2] === "goal") el(doc, "line", { x1: 2, y1: 7, x2: 32, y2: 7, stroke: it[1], "stroke-width": 2.5, "stroke-dasharray": "6 4" }, s);
      else { el(doc, "rect", { x: 9, y: 4, width: 16, height: 9, fill: "rgba(0,0,0,.3)" }, s); el(doc, "rect", { x: 6, y: 1, width: 16, height: 9, fill: "#bbb", stroke: "#444" }, s); }
      html(doc, "span", null, legend, it[0]);
    });

    // ---- drawing
    var ws = scene.workspace, W = ws.x[1] - ws.x[0], H = ws.y[1] - ws.y[0], m = 0.09 * Math.max(W, H);
    var svg = el(doc, "svg", {
      class: "lgv-svg", xmlns: SVGNS, role: "img",
      viewBox: [X(ws.x[0] - m * 0.5), Y(ws.y[1] + m * 0.5), X(W + m), X(H + m * 1.5)].join(" ")
    }, stage);
    el(doc, "title", {}, svg).textContent = "Top-down view of the table; the viewer stands at the bottom (\u2212y).";
    var defs = el(doc, "defs", {}, svg);
    ["goal", "relocate", "unstack"].forEach(function (p) {
      var mk = el(doc, "marker", { id: uid + "-arrow-" + p, viewBox: "0 0 10 10", refX: 9, refY: 5, markerWidth: 5, markerHeight: 5, orient: "auto-start-reverse", markerUnits: "strokeWidth" }, defs);
      el(doc, "path", { d: "M0 0 L10 5 L0 10 Z", fill: PURPOSE_COLORS[p] }, mk);
    });
    GOAL_COLORS.forEach(function (c, k) {
      var mk = el(doc, "marker", { id: uid + "-garrow-" + k, viewBox: "0 0 10 10", refX: 9, refY: 5, markerWidth: 4, markerHeight: 4, orient: "auto", markerUnits: "strokeWidth" }, defs);
      el(doc, "path", { d: "M0 0 L10 5 L0 10 Z", fill: c }, mk);
    });
    var fs = Math.max(W, H) * MM / 55; // label font size in drawing units
    // table, grid, viewer side, scale bar
    el(doc, "rect", { x: X(ws.x[0]), y: Y(ws.y[1]), width: X(W), height: X(H), fill: "#f4efe6", stroke: "#8a7f6d", "stroke-width": fs * 0.15 }, svg);
    var grid = el(doc, "g", { stroke: "#e2dacb", "stroke-width": fs * 0.08 }, svg);
    var gs = Math.max(W, H) > 2 ? 0.5 : 0.1;
    for (var gx = Math.ceil(ws.x[0] / gs) * gs; gx < ws.x[1] - 1e-9; gx += gs) el(doc, "line", { x1: X(gx), y1: Y(ws.y[0]), x2: X(gx), y2: Y(ws.y[1]) }, grid);
    for (var gy = Math.ceil(ws.y[0] / gs) * gs; gy < ws.y[1] - 1e-9; gy += gs) el(doc, "line", { x1: X(ws.x[0]), y1: Y(gy), x2: X(ws.x[1]), y2: Y(gy) }, grid);
    var vt = el(doc, "text", { x: X((ws.x[0] + ws.x[1]) / 2), y: Y(ws.y[0] - m * 0.55), "text-anchor": "middle", "font-size": fs * 1.1, "font-weight": "bold", fill: "#555" }, svg);
    vt.textContent = "\u25BC viewer side (front, \u2212y) \u25BC";
    var bt = el(doc, "text", { x: X((ws.x[0] + ws.x[1]) / 2), y: Y(ws.y[1] + m * 0.15), "text-anchor": "middle", "font-size": fs * 0.85, fill: "#999" }, svg);
    bt.textContent = "back (+y)";
    var L = [0.01, 0.02, 0.05, 0.1, 0.2, 0.25, 0.5, 1, 2, 5].filter(function (v) { return v >= W / 5 * 0.7; })[0] || 10;
    var sb = el(doc, "g", { class: "lgv-scalebar" }, svg);
    el(doc, "line", { x1: X(ws.x[0]), y1: Y(ws.y[0] - m * 0.6), x2: X(ws.x[0] + L), y2: Y(ws.y[0] - m * 0.6), stroke: "#222", "stroke-width": fs * 0.35 }, sb);
    var st = el(doc, "text", { x: X(ws.x[0] + L / 2), y: Y(ws.y[0] - m * 0.35), "text-anchor": "middle", "font-size": fs, fill: "#222" }, sb);
    st.textContent = Math.round(L * 100) + " cm";

    var gGoals = el(doc, "g", { class: "lgv-goal-shapes" }, svg);
    var gPaths = el(doc, "g", { class: "lgv-paths" }, svg);
    var gRings = el(doc, "g", { class: "lgv-rings" }, svg);
    var gObjs = el(doc, "g", { class: "lgv-objects" }, svg);
    var gRel = el(doc, "g", { class: "lgv-relations" }, svg);
    var gTop = el(doc, "g", { class: "lgv-top" }, svg);
    var gLabels = el(doc, "g", { class: "lgv-labels" }, svg);

    var localSvg = {}; // footprint in drawing units, object frame (y flipped)
    objects.forEach(function (o) {
      localSvg[o.id] = o.local.map(function (p) { return [X(p[0]), Y(p[1])]; });
    });
    function ptsLocal(id, scale) {
      scale = scale || 1;
      return localSvg[id].map(function (p) { return (p[0] * scale).toFixed(2) + "," + (p[1] * scale).toFixed(2); }).join(" ");
    }
    function radius(id) {
      return Math.max.apply(null, byId[id].local.map(function (p) { return Math.hypot(p[0], p[1]); }));
    }
    var nodes = {};
    objects.forEach(function (o) {
      var g = el(doc, "g", { class: "lgv-obj", "data-id": o.id }, gObjs);
      var tip = el(doc, "title", {}, g);
      var shadow = el(doc, "polygon", { class: "lgv-shadow", points: ptsLocal(o.id), fill: "rgba(0,0,0,0.3)" }, g);
      var body = el(doc, "g", {}, g);
      el(doc, "polygon", { class: "lgv-fill", points: ptsLocal(o.id), fill: o.paint.fill }, body);
      var tex = texturePattern(doc, defs, uid + "-tex-" + o.id, o.paint);
      if (tex) el(doc, "polygon", { points: ptsLocal(o.id), fill: tex, stroke: "none" }, body);
      var outline = el(doc, "polygon", { class: "lgv-outline", points: ptsLocal(o.id), fill: "none", stroke: o.paint.edge, "stroke-width": fs * 0.12 }, body);
      var rings = (member[o.id] || []).slice(0, 2).map(function (gk, j) {
        var r = radius(o.id);
        var grow = 1 + (0.01 + 0.006 * j) / Math.max(r, 1e-3);
        return el(doc, "polygon", { class: "lgv-ring", points: ptsLocal(o.id, grow), fill: "none", stroke: GOAL_COLORS[gk % GOAL_COLORS.length], "stroke-width": fs * 0.2 }, gRings);
      });
      var idText = el(doc, "text", { class: "lgv-id", "text-anchor": "middle", "dominant-baseline": "central", "font-size": fs * 1.05, "font-weight": "bold", fill: o.paint.ink }, gLabels);
      idText.textContent = String(o.id);
      var name = el(doc, "text", { class: "lgv-name", "text-anchor": "middle", "font-size": fs * 0.85, fill: "#333", stroke: "#fff", "stroke-width": fs * 0.25, "paint-order": "stroke" }, gLabels);
      name.textContent = o.name;
      nodes[o.id] = { g: g, tip: tip, shadow: shadow, outline: outline, rings: rings, idText: idText, name: name };
    });

    function level(frame, id) {
      var lv = 0, s = frame.on[id];
      while (s !== null && s !== undefined && lv < 64) { lv += 1; s = frame.on[s]; }
      return lv;
    }
    function holders(frame) {
      var out = {};
      for (var k in frame.on) if (frame.on[k] !== null && frame.on[k] !== undefined) out[String(frame.on[k])] = true;
      return out;
    }
    function placeObject(id, pose, lv) {
      var nd = nodes[id], tx = X(pose[0]), ty = Y(pose[1]), deg = -pose[2] * 180 / Math.PI;
      var tr = "translate(" + tx.toFixed(2) + "," + ty.toFixed(2) + ") rotate(" + deg.toFixed(3) + ")";
      nd.g.setAttribute("transform", tr);
      nd.rings.forEach(function (r) { r.setAttribute("transform", tr); });
      var off = Math.min(lv, 3) * 6;
      nd.shadow.setAttribute("transform", "rotate(" + (-deg).toFixed(3) + ") translate(" + off + "," + off + ") rotate(" + deg.toFixed(3) + ")");
      nd.shadow.style.display = lv ? "" : "none";
      nd.idText.setAttribute("x", tx.toFixed(2));
      nd.idText.setAttribute("y", ty.toFixed(2));
      var r = radius(id) * MM;
      nd.name.setAttribute("x", tx.toFixed(2));
      nd.name.setAttribute("y", (ty + r + fs * 0.95).toFixed(2));
    }

    function arc(a, b) {
      var ax = X(a[0]), ay = Y(a[1]), bx = X(b[0]), by = Y(b[1]);
      var mx = (ax + bx) / 2, my = (ay + by) / 2, dx = bx - ax, dy = by - ay;
      return "M" + ax.toFixed(1) + " " + ay.toFixed(1) + " Q" + (mx - dy * 0.18).toFixed(1) + " " + (my + dx * 0.18).toFixed(1) + " " + bx.toFixed(1) + " " + by.toFixed(1);
    }

    function drawGoals(shapes) {
      gGoals.innerHTML = "";
      gRel.innerHTML = "";
      shapes.forEach(function (s) {
        var col = GOAL_COLORS[s.index % GOAL_COLORS.length];
        var op = s.met === false ? 0.35 : 0.9;
        // Relation arrows go above the objects so their heads stay visible.
        var layer = s.kind === "relation" ? gRel : gGoals;
        var g = el(doc, "g", { class: "lgv-goal lgv-goal-" + s.index, opacity: op, fill: "none", stroke: col, "stroke-width": fs * 0.22, "stroke-dasharray": fs * 0.7 + " " + fs * 0.45 }, layer);
        if (s.region) {
          var rb = s.region;
          el(doc, "rect", { x: X(rb[0]), y: Y(rb[3]), width: (rb[1] - rb[0]) * MM, height: (rb[3] - rb[2]) * MM,
            fill: col, "fill-opacity": 0.06, "stroke-opacity": 0.5, "stroke-dasharray": fs * 0.15 + " " + fs * 0.3, class: "lgv-region" }, g);
        }
        if (s.heading !== undefined && s.anchor_point) {
          var hc = s.anchor_point, hl = 0.06, hx = hc[0] + hl * Math.cos(s.heading), hy = hc[1] + hl * Math.sin(s.heading);
          el(doc, "line", { x1: X(hc[0]), y1: Y(hc[1]), x2: X(hx), y2: Y(hy), "stroke-dasharray": "none", class: "lgv-heading",
            "marker-end": "url(#" + uid + "-garrow-" + (s.index % GOAL_COLORS.length) + ")" }, g);
        }
        if (s.kind === "line") {
          var p = s.points, d = [p[1][0] - p[0][0], p[1][1] - p[0][1]], L = Math.hypot(d[0], d[1]) || 1, e = 0.03;
          el(doc, "line", { x1: X(p[0][0] - d[0] / L * e), y1: Y(p[0][1] - d[1] / L * e), x2: X(p[1][0] + d[0] / L * e), y2: Y(p[1][1] + d[1] / L * e) }, g);
        } else if (s.kind === "circle" && s.radius > 0) {
          el(doc, "circle", { cx: X(s.centre[0]), cy: Y(s.centre[1]), r: s.radius * MM }, g);
          el(doc, "path", { d: "M" + (X(s.centre[0]) - fs * 0.6) + " " + Y(s.centre[1]) + " h" + fs * 1.2 + " M" + X(s.centre[0]) + " " + (Y(s.centre[1]) - fs * 0.6) + " v" + fs * 1.2, "stroke-dasharray": "none" }, g);
        } else if (s.kind === "rectangle") {
          el(doc, "polygon", { points: pointsAttr(s.corners) }, g);
        } else if (s.kind === "relation") {
          g.setAttribute("stroke-dasharray", "none");
          s.arrows.forEach(function (ab) {
            var a = ab[0], b = ab[1], dx = b[0] - a[0], dy = b[1] - a[1], L = Math.hypot(dx, dy);
            if (L < 1e-6) return;
            var sa = Math.min(0.02, L * 0.25), sb = Math.min(0.012, L * 0.2);
            el(doc, "line", { x1: X(a[0] + dx / L * sa), y1: Y(a[1] + dy / L * sa), x2: X(b[0] - dx / L * sb), y2: Y(b[1] - dy / L * sb), "marker-end": "url(#" + uid + "-garrow-" + (s.index % GOAL_COLORS.length) + ")" }, g);
          });
        } else if (s.kind === "tower") {
          el(doc, "circle", { cx: X(s.centre[0]), cy: Y(s.centre[1]), r: (radius(s.levels[0]) + 0.016) * MM }, g);
        } else if (s.kind === "pose") {
          var id0 = goals[s.index].objects[0];
          el(doc, "polygon", { points: pointsAttr(transform(byId[id0].local, s.target)), "stroke-dasharray": fs * 0.25 + " " + fs * 0.25 }, g);
        } else if (s.kind === "points") {
          s.points.forEach(function (q) { el(doc, "circle", { cx: X(q[0]), cy: Y(q[1]), r: fs * 0.9 }, g); });
        }
      });
    }

    var state = { step: 0, playing: false, timer: null, anim: null, listeners: [] };

    function show(k, animate) {
      k = Math.max(0, Math.min(n, k | 0));
      var prevStep = state.step;
      state.step = k;
      var f = frameAt(k), held = holders(f);
      // stacking order: lower objects first
      objects.slice().sort(function (a, b) { return level(f, a.id) - level(f, b.id) || 0; }).forEach(function (o) {
        gObjs.appendChild(nodes[o.id].g);
      });
      objects.forEach(function (o) {
        var nd = nodes[o.id], p = f.poses[o.id], lv = level(f, o.id);
        nd.g.setAttribute("data-x", String(p[0]));
        nd.g.setAttribute("data-y", String(p[1]));
        nd.g.setAttribute("data-theta", String(p[2]));
        nd.g.setAttribute("data-on", f.on[o.id] === null || f.on[o.id] === undefined ? "" : String(f.on[o.id]));
        placeObject(o.id, p, lv);
        nd.tip.textContent = o.id + " " + (o.color ? o.color + " " : "") + o.name + "\n(x, y, \u03b8) = (" + fmt(p[0]) + " m, " + fmt(p[1]) + " m, " + fmt(p[2]) + " rad)" +
          (f.on[o.id] !== null && f.on[o.id] !== undefined ? "\non " + f.on[o.id] : "") + (member[o.id] ? "\ngoal: " + member[o.id].map(function (g) { return goalText[g]; }).join("; ") : "");
        nd.outline.setAttribute("stroke", o.paint.edge);
        nd.outline.setAttribute("stroke-width", fs * 0.12);
        nd.idText.style.display = held[String(o.id)] ? "none" : "";
        nd.name.style.display = lv ? "none" : "";
      });
      gPaths.innerHTML = "";
      gTop.innerHTML = "";
      for (var j = 0; j < k - 1; j++) {
        var aj = actions[j];
        el(doc, "path", { d: arc(before[j], aj.to), fill: "none", stroke: "#8d8d8d", "stroke-width": fs * 0.1, opacity: 0.6 }, gPaths);
      }
      var cap;
      if (k > 0) {
        var a = actions[k - 1], col = PURPOSE_COLORS[a.purpose || "goal"], before0 = before[k - 1];
        el(doc, "polygon", { class: "lgv-ghost", points: pointsAttr(transform(byId[a.object].local, before0)), fill: "none", stroke: col, "stroke-width": fs * 0.15, "stroke-dasharray": fs * 0.5 + " " + fs * 0.35 }, gTop);
        el(doc, "path", { class: "lgv-move", d: arc(before0, a.to), fill: "none", stroke: col, "stroke-width": fs * 0.28, "marker-end": "url(#" + uid + "-arrow-" + (a.purpose || "goal") + ")" }, gTop);
        nodes[a.object].outline.setAttribute("stroke", col);
        nodes[a.object].outline.setAttribute("stroke-width", fs * 0.35);
        var o = byId[a.object];
        cap = "Step " + k + " of " + n + ": " + PURPOSE_WORDS[a.purpose || "goal"] + " " + o.id + " " + (o.color ? o.color + " " : "") + o.name +
          (a.on !== null && a.on !== undefined ? " onto " + a.on : "") + " \u2192 (" + fmt(a.to[0]) + ", " + fmt(a.to[1]) + ", " + fmt(a.to[2]) + " rad)";
        caption.style.borderLeftColor = col;
        if (animate && prevStep === k - 1) tween(a.object, before0, a.to, level(f, a.object));
      } else {
        cap = "Start: " + objects.length + " objects. Press play or pick a step.";
        caption.style.borderLeftColor = "#ccc";
      }
      caption.textContent = cap;
      var shapes = f.goals;
      drawGoals(shapes);
      if (goalList) {
        goalList.innerHTML = "";
        goals.forEach(function (g, gk) {
          var s = shapes[gk] || {}, li = html(doc, "li", s.met === true ? "lgv-met" : s.met === false ? "lgv-unmet" : "", goalList);
          li.setAttribute("data-goal", String(gk));
          var sw = html(doc, "span", "lgv-swatch", li);
          sw.style.background = GOAL_COLORS[gk % GOAL_COLORS.length];
          html(doc, "span", "lgv-status", li, s.met === true ? "\u2713" : s.met === false ? "\u2717" : "\u2022");
          html(doc, "span", null, li, goalText[gk]);
          if (s.problem) li.title = s.problem;
          li.addEventListener("mouseenter", function () { g.objects.forEach(function (i) { nodes[i].g.classList.add("lgv-hl"); }); });
          li.addEventListener("mouseleave", function () { g.objects.forEach(function (i) { nodes[i].g.classList.remove("lgv-hl"); }); });
        });
      }
      [startItem].concat(actItems).forEach(function (li, j) {
        li.classList.toggle("lgv-current", j === k);
        li.classList.toggle("lgv-future", j > k);
      });
      var cur = k === 0 ? startItem : actItems[k - 1];
      if (cur && cur.scrollIntoView && actList.scrollHeight > actList.clientHeight) {
        var top = cur.offsetTop - actList.offsetTop;
        if (top < actList.scrollTop || top > actList.scrollTop + actList.clientHeight - cur.offsetHeight) actList.scrollTop = top - actList.clientHeight / 2;
      }
      slider.value = String(k);
      stepNo.textContent = "step " + k + " / " + n;
      root.setAttribute("data-step", String(k));
      state.listeners.forEach(function (cb) { cb(k); });
    }

    function tween(id, a, b, lv) {
      if (state.anim) cancelAnimationFrame(state.anim);
      var t0 = null, dur = 450;
      var dth = Math.atan2(Math.sin(b[2] - a[2]), Math.cos(b[2] - a[2]));
      function frame(ts) {
        if (t0 === null) t0 = ts;
        var u = Math.min(1, (ts - t0) / dur), e = u < 0.5 ? 2 * u * u : 1 - Math.pow(-2 * u + 2, 2) / 2;
        placeObject(id, [a[0] + (b[0] - a[0]) * e, a[1] + (b[1] - a[1]) * e, a[2] + dth * e], lv);
        if (u < 1) state.anim = requestAnimationFrame(frame);
        else { state.anim = null; placeObject(id, b, lv); }
      }
      state.anim = requestAnimationFrame(frame);
    }

    function pause() {
      state.playing = false;
      if (state.timer) clearInterval(state.timer);
      state.timer = null;
      bPlay.textContent = "\u25B6 Play";
    }
    function play() {
      if (n === 0) return;
      if (state.step >= n) show(0, false);
      state.playing = true;
      bPlay.textContent = "\u275A\u275A Pause";
      state.timer = setInterval(function () {
        if (state.step >= n) { pause(); return; }
        show(state.step + 1, true);
        if (state.step >= n) pause();
      }, 1100);
    }

    bPlay.addEventListener("click", function () { if (state.playing) pause(); else play(); });
    bPrev.addEventListener("click", function () { pause(); show(state.step - 1, false); });
    bNext.addEventListener("click", function () { pause(); show(state.step + 1, true); });
    slider.addEventListener("input", function () { pause(); show(parseInt(slider.value, 10), false); });
    [startItem].concat(actItems).forEach(function (li) {
      li.addEventListener("click", function () { pause(); show(parseInt(li.getAttribute("data-step"), 10), false); });
    });
    root.addEventListener("keydown", function (ev) {
      if (ev.target && ev.target.tagName === "INPUT") return;
      if (ev.key === "ArrowRight") { pause(); show(state.step + 1, true); }
      else if (ev.key === "ArrowLeft") { pause(); show(state.step - 1, false); }
      else if (ev.key === " ") { if (state.playing) pause(); else play(); }
      else if (ev.key === "Home") { pause(); show(0, false); }
      else if (ev.key === "End") { pause(); show(n, false); }
      else return;
      ev.preventDefault();
    });

    show(0, false);

    var api = {
      setStep: function (k) { pause(); show(k, false); return state.step; },
      next: function () { pause(); show(state.step + 1, false); return state.step; },
      prev: function () { pause(); show(state.step - 1, false); return state.step; },
      play: play,
      pause: pause,
      toggle: function () { if (state.playing) pause(); else play(); },
      step: function () { return state.step; },
      count: function () { return n; },
      playing: function () { return state.playing; },
      poses: function () {
        var out = {}, f = frameAt(state.step);
        for (var k in f.poses) out[k] = f.poses[k].slice();
        return out;
      },
      onStep: function (cb) { state.listeners.push(cb); },
      destroy: function () { pause(); if (state.anim) cancelAnimationFrame(state.anim); container.innerHTML = ""; }
    };
    container.lgmctsViewer = api;
    return api;
  }

  global.LGMCTSViewer = {
    render: render,
    version: "2"
  };
})(typeof window !== "undefined" ? window : this);
