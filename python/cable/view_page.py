# SPDX-License-Identifier: GPL-3.0-or-later
"""The HTML, CSS and JavaScript of the page `cable view` writes (cable.view
fills in the data).  One self-contained file: three.js (Debian's libjs-three)
is embedded by cable.view, the diagram is SVG drawn here, the solutions come
as base64 float32 arrays computed by the C analysis (doc/view.md)."""

__all__ = ['CSS', 'BODY', 'JS']

CSS = r"""
body { font: 13px/1.35 sans-serif; margin: 0; color: #222; background: #fff; }
header { padding: 6px 10px; background: #f3f3f3; border-bottom: 1px solid #ccc; }
header h1 { font-size: 15px; margin: 0; display: inline; }
#main { display: flex; flex-wrap: wrap; gap: 8px; padding: 8px; }
#left, #right { flex: 1 1 520px; min-width: 420px; }
#diagram { width: 100%; height: 480px; border: 1px solid #ccc; background: #fff;
    cursor: crosshair; }
#diagram .pt { cursor: pointer; }
#diagram .sel { fill: none; stroke: #d00; stroke-width: 2.5; }
#view3d { width: 100%; height: 480px; border: 1px solid #ccc; position: relative; }
#view3d canvas { display: block; }
#colorbar { position: absolute; right: 6px; top: 10px; width: 60px; height: 220px; }
#tip { position: fixed; pointer-events: none; background: #ffffe8; border: 1px solid #999;
    padding: 3px 6px;
       font: 12px monospace; white-space: pre; display: none; z-index: 10; }
.controls { margin: 4px 0; }
.controls label { margin-right: 10px; }
#info { font: 12px monospace; white-space: pre; background: #fafafa; border: 1px solid #ddd;
    padding: 4px 6px; }
#slider { width: 70%; vertical-align: middle; }
#tasks { max-height: 300px; overflow: auto; border: 1px solid #ccc; margin: 8px; }
#tasks table { border-collapse: collapse; font-size: 12px; }
#tasks td, #tasks th { padding: 1px 6px; border-bottom: 1px solid #eee; text-align: left; }
#tasks tr.task { cursor: pointer; }
#tasks tr.task:hover { background: #eef; }
#tasks tr.nofiles { color: #888; }
#tasks tr.current { background: #dde; }
.legend text { font-size: 11px; }
#overlap.yes { color: #c00; font-weight: bold; }
"""

BODY = r"""
<header><h1 id="title"></h1> <span id="subtitle"></span></header>
<div id="tasks" style="display:none"></div>
<div id="main">
 <div id="left">
  <div class="controls">
   <label>x <select id="xcol"></select></label>
   <label>y <select id="ycol"></select></label>
   <button id="reset">reset zoom</button>
   <span style="color:#666">wheel: zoom, drag: pan, click a circle: show its solution</span>
  </div>
  <svg id="diagram" xmlns="http://www.w3.org/2000/svg"></svg>
 </div>
 <div id="right">
  <div class="controls">
   <label>branch <select id="branch"></select></label>
   <label><input type="checkbox" id="axis"> braid axis</label>
  </div>
  <div id="view3d"><canvas id="colorbar" width="60" height="220"></canvas></div>
  <div class="controls"><input type="range" id="slider" min="0" max="0" value="0">
      <span id="slidertext"></span></div>
  <div id="info"></div>
 </div>
</div>
<div id="tip"></div>
"""

# The viewer.  DATA (set before this script) is either a run
# {kind: 'run', title, columns, branches: [...]} or an atlas
# {kind: 'atlas', title, tasks: [{name, rows, run or null}]}.
JS = r"""
(function () {
'use strict';
var PALETTE = ['#4e79a7', '#f28e2b', '#e15759', '#76b7b2', '#59a14f', '#edc948',
    '#b07aa1', '#ff9da7',
               '#9c755f', '#bab0ac'];
var TYPES = {1: 'BP', 2: 'LP', 3: 'HB', 4: 'RG', 5: 'LP', 6: 'BP', 7: 'PD', 8: 'TR',
    9: 'EP', '-9': 'MX',
             '-4': 'UZ'};
var SVGNS = 'http://www.w3.org/2000/svg';
var $ = function (id) { return document.getElementById(id); };

function b64floats(s) {
  var bin = atob(s), n = bin.length, buf = new ArrayBuffer(n), u8 = new Uint8Array(buf);
  for (var i = 0; i < n; i++) u8[i] = bin.charCodeAt(i);
  return new Float32Array(buf);
}
function typeName(t) {
  var base = Math.abs(t) % 10, k = String(t < 0 && base === 4 ? -4 : t < 0 && base === 9
      ? -9 : base);
  return TYPES[k] || String(t);
}
function fmt(x) {
  if (x === undefined || x === null) return '';
  if (typeof x !== 'number') return String(x);
  if (x !== 0 && (Math.abs(x) >= 1e6 || Math.abs(x) < 1e-4)) return x.toExponential(6);
  return Number(x.toPrecision(8)).toString();
}

// ---------------------------------------------------------------- state
var run = null;          // the run shown (DATA itself, or an atlas task's run)
var view = {x: null, y: null, box: null};
var cur = {b: -1, s: -1};
window.cableView = {ready: false, error: null, state: cur, select: null, info: {}};

// ---------------------------------------------------------------- diagram
var W = 0, H = 0, M = {l: 70, r: 12, t: 12, b: 42};
function niceStep(span, n) {
  var raw = span / n, p = Math.pow(10, Math.floor(Math.log10(raw))), f = raw / p;
  return (f < 1.5 ? 1 : f < 3.5 ? 2 : f < 7.5 ? 5 : 10) * p;
}
function column(b, name) {
  if (!b.cols) { b.cols = b.data ? b64floats(b.data) : new Float32Array(0); b.colcache = {}; }
  if (!b.colcache[name]) {
    var k = run.columns.indexOf(name);
    b.colcache[name] = b.cols.subarray(k * b.npt, (k + 1) * b.npt);
  }
  return b.colcache[name];
}
function dataBox() {
  var x0 = Infinity, x1 = -Infinity, y0 = Infinity, y1 = -Infinity;
  run.branches.forEach(function (b) {
    var xs = column(b, view.x), ys = column(b, view.y);
    for (var i = 0; i < b.npt; i++) {
      if (!isFinite(xs[i]) || !isFinite(ys[i])) continue;
      x0 = Math.min(x0, xs[i]); x1 = Math.max(x1, xs[i]); y0 = Math.min(y0, ys[i]);
          y1 = Math.max(y1, ys[i]);
    }
  });
  if (!isFinite(x0)) { x0 = 0; x1 = 1; y0 = 0; y1 = 1; }
  if (x1 - x0 < 1e-12) { x0 -= 1; x1 += 1; }
  if (y1 - y0 < 1e-12) { y0 -= 1; y1 += 1; }
  var dx = 0.04 * (x1 - x0), dy = 0.05 * (y1 - y0);
  return [x0 - dx, x1 + dx, y0 - dy, y1 + dy];
}
function sx(x) { return M.l + (x - view.box[0]) / (view.box[1] - view.box[0]) * (W - M.l - M.r); }
function sy(y) {
  return H - M.b - (y - view.box[2]) / (view.box[3] - view.box[2]) * (H - M.t - M.b);
}
function el(name, attrs, parent) {
  var e = document.createElementNS(SVGNS, name);
  for (var k in attrs) e.setAttribute(k, attrs[k]);
  if (parent) parent.appendChild(e);
  return e;
}
function drawDiagram() {
  var svg = $('diagram');
  W = svg.clientWidth || 600; H = svg.clientHeight || 480;
  while (svg.firstChild) svg.removeChild(svg.firstChild);
  var defs = el('defs', {}, svg), cp = el('clipPath', {id: 'plotarea'}, defs);
  el('rect', {x: M.l, y: M.t, width: W - M.l - M.r, height: H - M.t - M.b}, cp);
  var grid = el('g', {stroke: '#e4e4e4'}, svg), ticks = el('g', {'font-size': 11,
      fill: '#333'}, svg);
  var b = view.box, xs = niceStep(b[1] - b[0], 8), ys = niceStep(b[3] - b[2], 7);
  for (var x = Math.ceil(b[0] / xs) * xs; x <= b[1]; x += xs) {
    el('line', {x1: sx(x), x2: sx(x), y1: M.t, y2: H - M.b}, grid);
    el('text', {x: sx(x), y: H - M.b + 14, 'text-anchor': 'middle'},
        ticks).textContent = fmt(Math.round(x / xs) * xs);
  }
  for (var y = Math.ceil(b[2] / ys) * ys; y <= b[3]; y += ys) {
    el('line', {x1: M.l, x2: W - M.r, y1: sy(y), y2: sy(y)}, grid);
    el('text', {x: M.l - 4, y: sy(y) + 4, 'text-anchor': 'end'},
        ticks).textContent = fmt(Math.round(y / ys) * ys);
  }
  el('rect', {x: M.l, y: M.t, width: W - M.l - M.r, height: H - M.t - M.b, fill: 'none',
      stroke: '#444'}, svg);
  el('text', {x: (M.l + W - M.r) / 2, y: H - 8, 'text-anchor': 'middle', 'font-size': 13},
      svg).textContent = view.x;
  el('text', {x: 14, y: (M.t + H - M.b) / 2, 'text-anchor': 'middle', 'font-size': 13,
              transform: 'rotate(-90 14 ' + (M.t + H - M.b) / 2 + ')'}, svg).textContent = view.y;
  // lines, then open circles and texts, then branch points on top (a branch
  // starts at another's branch point: the BP stays visible)
  var g = el('g', {'clip-path': 'url(#plotarea)'}, svg), marks = el('g',
      {'clip-path': 'url(#plotarea)'}, svg);
  var bpg = el('g', {'clip-path': 'url(#plotarea)'}, svg);
  run.branches.forEach(function (br, bi) {
    var X = column(br, view.x), Y = column(br, view.y), d = '', pen = false;
    var color = PALETTE[bi % PALETTE.length];
    for (var i = 0; i < br.npt; i++) {
      if (!isFinite(X[i]) || !isFinite(Y[i])) { pen = false; continue; }
      d += (pen ? 'L' : 'M') + sx(X[i]).toFixed(1) + ' ' + sy(Y[i]).toFixed(1);
      pen = true;
    }
    el('path', {d: d, fill: 'none', stroke: color, 'stroke-width': 1.6}, g);
    // folds: open triangles; branch points: filled black circles
    for (i = 0; i < br.npt; i++) {
      var t = typeName(br.ty[i]);
      if (t === 'LP') el('path', {d: 'M' + sx(X[i]) + ' ' + (sy(Y[i]) - 6) + 'l5 9h-10z',
          fill: 'none',
                                  stroke: '#000', 'stroke-width': 1.2}, marks);
    }
    br.sols.forEach(function (s, si) {
      var cx = sx(X[s.row]), cy = sy(Y[s.row]), isbp = s.ty === 'BP';
      var c = el('circle', {cx: cx, cy: cy, r: isbp ? 4 : 4.5, fill: isbp ? '#000' : '#fff',
          stroke: '#000',
                            'stroke-width': 1.2, 'class': 'pt', 'data-branch': bi,
                                'data-index': si,
                            'data-lab': s.lab, 'data-ty': s.ty}, isbp ? bpg : marks);
      c.addEventListener('click', function () { select(bi, si); });
      c.addEventListener('mousemove', function (ev) { tip(ev, br, s.row, s); });
      c.addEventListener('mouseleave', function () { $('tip').style.display = 'none'; });
      el('text', {x: cx + 6, y: cy - 5, 'font-size': 10, fill: '#333'}, marks).textContent =
        s.text ? s.text : (s.ty === 'RG' ? '' : String(s.lab));
    });
  });
  if (cur.b >= 0) {
    var s = run.branches[cur.b].sols[cur.s], br2 = run.branches[cur.b];
    el('circle', {cx: sx(column(br2, view.x)[s.row]), cy: sy(column(br2, view.y)[s.row]), r: 8,
        'class': 'sel',
                  id: 'selmark'}, bpg);
  }
  // legend: the branch names, in the corner of the plot that hides the fewest points
  var lw = 150, lh = 14 * run.branches.length + 6, pad = 4;
  var corners = [[W - M.r - lw - pad, M.t + pad], [M.l + pad, M.t + pad], [W - M.r - lw - pad,
      H - M.b - lh - pad],
                 [M.l + pad, H - M.b - lh - pad]];
  var best = 0, fewest = Infinity;
  corners.forEach(function (c, k) {
    var n = 0;
    run.branches.forEach(function (br) {
      var X = column(br, view.x), Y = column(br, view.y);
      for (var i = 0; i < br.npt; i++) {
        var px = sx(X[i]), py = sy(Y[i]);
        if (px >= c[0] && px <= c[0] + lw && py >= c[1] && py <= c[1] + lh) n++;
      }
    });
    if (n < fewest) { fewest = n; best = k; }
  });
  var lx = corners[best][0], ly = corners[best][1] + 14;
  var lg = el('g', {'class': 'legend'}, svg);
  el('rect', {x: lx, y: corners[best][1], width: lw, height: lh, fill: '#fff',
      'fill-opacity': 0.85, stroke: '#bbb'}, lg);
  run.branches.forEach(function (br, bi) {
    el('line', {x1: lx + 6, x2: lx + 26, y1: ly - 4, y2: ly - 4,
        stroke: PALETTE[bi % PALETTE.length],
                'stroke-width': 2.5}, lg);
    el('text', {x: lx + 32, y: ly}, lg).textContent = br.name;
    ly += 14;
  });
}
function tip(ev, br, row, s) {
  var lines = [br.name + '  PT ' + br.pt[row] + (s ? '  LAB ' + s.lab + ' ' + s.ty : '')];
  run.columns.forEach(function (c) { lines.push(c + ' = ' + fmt(column(br, c)[row])); });
  if (s && s.a) {
    lines.push('Lk = ' + fmt(s.a.Lk) + '   axis: ' + s.a.knot);
    lines.push('tubes ' + (s.a.noverlap > 0 ? 'overlap' : 'do not overlap') + ' (dmin/Delta = '
        + fmt(s.a.dmin) + ')');
  }
  var t = $('tip');
  t.textContent = lines.join('\n');
  t.style.left = (ev.clientX + 14) + 'px'; t.style.top = (ev.clientY + 10) + 'px';
      t.style.display = 'block';
}
function setupDiagram() {
  var svg = $('diagram'), drag = null;
  svg.addEventListener('wheel', function (ev) {
    ev.preventDefault();
    var r = svg.getBoundingClientRect(), px = ev.clientX - r.left, py = ev.clientY - r.top;
    var x = view.box[0] + (px - M.l) / (W - M.l - M.r) * (view.box[1] - view.box[0]);
    var y = view.box[2] + (H - M.b - py) / (H - M.t - M.b) * (view.box[3] - view.box[2]);
    var f = ev.deltaY > 0 ? 1.25 : 0.8;
    view.box = [x + (view.box[0] - x) * f, x + (view.box[1] - x) * f, y + (view.box[2] - y) * f,
        y + (view.box[3] - y) * f];
    drawDiagram();
  }, {passive: false});
  svg.addEventListener('mousedown', function (ev) { drag = {x: ev.clientX, y: ev.clientY,
      box: view.box.slice()}; });
  window.addEventListener('mouseup', function () { drag = null; });
  // hover anywhere near a branch: the nearest row (within 8 px) and its values
  svg.addEventListener('mousemove', function (ev) {
    if (drag || (ev.target && ev.target.classList && ev.target.classList.contains('pt'))) return;
    var r = svg.getBoundingClientRect(), px = ev.clientX - r.left, py = ev.clientY - r.top,
        best = null, bd = 64;
    run.branches.forEach(function (br) {
      var X = column(br, view.x), Y = column(br, view.y);
      for (var i = 0; i < br.npt; i++) {
        var dx = sx(X[i]) - px, dy = sy(Y[i]) - py, d2 = dx * dx + dy * dy;
        if (d2 < bd) { bd = d2; best = [br, i]; }
      }
    });
    if (best) tip(ev, best[0], best[1], null); else $('tip').style.display = 'none';
  });
  svg.addEventListener('mouseleave', function () { $('tip').style.display = 'none'; });
  window.addEventListener('mousemove', function (ev) {
    if (!drag) return;
    var dx = (ev.clientX - drag.x) / (W - M.l - M.r) * (drag.box[1] - drag.box[0]);
    var dy = (ev.clientY - drag.y) / (H - M.t - M.b) * (drag.box[3] - drag.box[2]);
    if (Math.abs(ev.clientX - drag.x) + Math.abs(ev.clientY - drag.y) < 3) return;
    view.box = [drag.box[0] - dx, drag.box[1] - dx, drag.box[2] + dy, drag.box[3] + dy];
    drawDiagram();
  });
  $('reset').onclick = function () { view.box = dataBox(); drawDiagram(); };
  $('xcol').onchange = function () { view.x = this.value; view.box = dataBox(); drawDiagram(); };
  $('ycol').onchange = function () { view.y = this.value; view.box = dataBox(); drawDiagram(); };
}

// ---------------------------------------------------------------- 3-D view
var three = null;
// the colour of pressure v: viridis over [lo, hi] when the pressure keeps one
// sign, blue-white-red over [-m, m] when it changes sign (as graphics/render_colormap.c)
var VIRIDIS = [[0.267, 0.005, 0.329], [0.283, 0.141, 0.458], [0.254, 0.265, 0.530], [0.207,
    0.372, 0.553],
               [0.164, 0.471, 0.558], [0.128, 0.567, 0.551], [0.135, 0.659, 0.518], [0.267,
                   0.749, 0.441],
               [0.478, 0.821, 0.318], [0.741, 0.873, 0.150], [0.993, 0.906, 0.144]];
function pcolor(v, cm) {
  if (cm.div) {
    var t = cm.m > 0 ? Math.max(-1, Math.min(1, v / cm.m)) : 0;
    return t < 0 ? [1 + t * 0.83, 1 + t * 0.6, 1 + t * 0.15] : [1 - t * 0.15, 1 - t * 0.8,
        1 - t * 0.85];
  }
  var u = cm.hi > cm.lo ? Math.max(0, Math.min(1, (v - cm.lo) / (cm.hi - cm.lo))) : 0.5;
  var x = u * (VIRIDIS.length - 1), k = Math.min(VIRIDIS.length - 2, Math.floor(x)), f = x - k;
  return [0, 1, 2].map(function (j) { return VIRIDIS[k][j] * (1 - f) + VIRIDIS[k + 1][j] * f; });
}
function colormapFor(p1, p2, n) {
  var lo = Infinity, hi = -Infinity;
  for (var i = 0; i < n; i++) { lo = Math.min(lo, p1[i], p2[i]); hi = Math.max(hi, p1[i], p2[i]); }
  return {div: lo < 0 && hi > 0, lo: lo, hi: hi, m: Math.max(Math.abs(lo), Math.abs(hi))};
}
function setup3d() {
  var box = $('view3d');
  // A software WebGL (SwiftShader, llvmpipe) takes seconds to set up a
  // multisampled context: there the page draws without antialiasing, on the
  // context it probed with (WEBGL_debug_renderer_info names the renderer).
  var canvas = document.createElement('canvas');
  var attrs = {antialias: false, preserveDrawingBuffer: true, alpha: false, depth: true,
      stencil: false};
  var gl = canvas.getContext('webgl', attrs);
  if (!gl) throw new Error('no WebGL context');
  var dbg = gl.getExtension('WEBGL_debug_renderer_info');
  var name = dbg ? String(gl.getParameter(dbg.UNMASKED_RENDERER_WEBGL)) : '';
  var software = /swiftshader|llvmpipe|software/i.test(name);
  window.cableView.webgl = {renderer: name, software: software};
  var renderer = software ? new THREE.WebGLRenderer({canvas: canvas, context: gl,
      preserveDrawingBuffer: true})
                          : new THREE.WebGLRenderer({antialias: true,
                              preserveDrawingBuffer: true});
  renderer.setPixelRatio(1);
  renderer.setSize(box.clientWidth, box.clientHeight);
  renderer.setClearColor(0xffffff, 1);
  box.insertBefore(renderer.domElement, box.firstChild);
  renderer.domElement.id = 'canvas3d';
  var scene = new THREE.Scene();
  var camera = new THREE.PerspectiveCamera(30, box.clientWidth / box.clientHeight, 0.001, 1000);
  scene.add(new THREE.AmbientLight(0xffffff, 0.45));
  var light = new THREE.DirectionalLight(0xffffff, 0.65);
  camera.add(light); light.position.set(-1, 1, 2);
  scene.add(camera);
  var controls = new THREE.OrbitControls(camera, renderer.domElement);
  controls.addEventListener('change', function () { renderer.render(scene, camera); });
  three = {renderer: renderer, scene: scene, camera: camera, controls: controls, group: null,
      fitted: null};
}
// a tube of radius r around the centre line P (n points), rings on parallel-transported frames
function tubeGeometry(P, n, r, closed, colors) {
  var m = 16, pos = new Float32Array(n * m * 3), nor = new Float32Array(n * m * 3),
      col = new Float32Array(n * m * 3);
  var T = [], i, k;
  for (i = 0; i < n; i++) {
    var a = i > 0 ? i - 1 : (closed ? n - 2 : 0), b = i < n - 1 ? i + 1 : (closed ? 1 : n - 1);
    var t = new THREE.Vector3(P[3 * b] - P[3 * a], P[3 * b + 1] - P[3 * a + 1],
        P[3 * b + 2] - P[3 * a + 2]);
    if (t.lengthSq() === 0) t.set(0, 0, 1);
    T.push(t.normalize());
  }
  var N = new THREE.Vector3(0, 0, 1);
  if (Math.abs(N.dot(T[0])) > 0.9) N.set(1, 0, 0);
  N.sub(T[0].clone().multiplyScalar(N.dot(T[0]))).normalize();
  for (i = 0; i < n; i++) {
    if (i > 0) { N.sub(T[i].clone().multiplyScalar(N.dot(T[i]))).normalize(); }
    var B = new THREE.Vector3().crossVectors(T[i], N);
    for (k = 0; k < m; k++) {
      var ph = 2 * Math.PI * k / m, c = Math.cos(ph), s = Math.sin(ph), j = 3 * (i * m + k);
      var nx = c * N.x + s * B.x, ny = c * N.y + s * B.y, nz = c * N.z + s * B.z;
      pos[j] = P[3 * i] + r * nx; pos[j + 1] = P[3 * i + 1] + r * ny;
          pos[j + 2] = P[3 * i + 2] + r * nz;
      nor[j] = nx; nor[j + 1] = ny; nor[j + 2] = nz;
      col[j] = colors[3 * i]; col[j + 1] = colors[3 * i + 1]; col[j + 2] = colors[3 * i + 2];
    }
  }
  var idx = [];
  for (i = 0; i < n - 1; i++)
    for (k = 0; k < m; k++) {
      var a0 = i * m + k, a1 = i * m + (k + 1) % m, b0 = a0 + m, b1 = a1 + m;
      idx.push(a0, b0, a1, a1, b0, b1);
    }
  var g = new THREE.BufferGeometry();
  g.setAttribute('position', new THREE.BufferAttribute(pos, 3));
  g.setAttribute('normal', new THREE.BufferAttribute(nor, 3));
  g.setAttribute('color', new THREE.BufferAttribute(col, 3));
  g.setIndex(idx);
  return g;
}
function solutionArrays(br, s) {
  if (!br.geom) br.geom = b64floats(br.geometry);
  var n = s.n, o = s.off;
  return {r1: br.geom.subarray(o, o + 3 * n), r2: br.geom.subarray(o + 3 * n, o + 6 * n),
          p1: br.geom.subarray(o + 6 * n, o + 7 * n), p2: br.geom.subarray(o + 7 * n, o + 8 * n)};
}
function drawColorbar(cm) {
  var c = $('colorbar'), ctx = c.getContext('2d');
  ctx.clearRect(0, 0, c.width, c.height);
  var x0 = 4, y0 = 28, h = c.height - 40, w = 14, top = cm.div ? cm.m : cm.hi,
      bot = cm.div ? -cm.m : cm.lo;
  for (var i = 0; i < h; i++) {
    var rgb = pcolor(top + (bot - top) * i / (h - 1), cm);
    ctx.fillStyle = 'rgb(' + Math.round(255 * rgb[0]) + ',' + Math.round(255 * rgb[1]) + ','
        + Math.round(255 * rgb[2]) + ')';
    ctx.fillRect(x0, y0 + i, w, 1);
  }
  ctx.strokeStyle = '#444'; ctx.strokeRect(x0, y0, w, h);
  ctx.fillStyle = '#222'; ctx.font = '10px sans-serif';
  ctx.fillText('contact', 2, 9);
  ctx.fillText('pressure', 2, 20);
  var r3 = function (x) { return fmt(Number(x.toPrecision(3))); };
  ctx.fillText(r3(top), x0 + w + 3, y0 + 4);
  ctx.fillText(r3(cm.div ? 0 : (top + bot) / 2), x0 + w + 3, y0 + h / 2 + 4);
  ctx.fillText(r3(bot), x0 + w + 3, y0 + h + 4);
}
function show3d(br, s) {
  var A = solutionArrays(br, s), n = s.n, i;
  var cm = colormapFor(A.p1, A.p2, n);
  var c1 = new Float32Array(3 * n), c2 = new Float32Array(3 * n), ax = new Float32Array(3 * n);
  for (i = 0; i < n; i++) {
    var q1 = pcolor(A.p1[i], cm), q2 = pcolor(A.p2[i], cm);
    c1.set(q1, 3 * i); c2.set(q2, 3 * i);
    for (var d = 0; d < 3; d++) ax[3 * i + d] = 0.5 * (A.r1[3 * i + d] + A.r2[3 * i + d]);
  }
  if (three.group) {
    three.scene.remove(three.group);
    three.group.traverse(function (o) { if (o.geometry) o.geometry.dispose(); });
  }
  var grp = new THREE.Group();
  var mat = new THREE.MeshPhongMaterial({vertexColors: THREE.VertexColors, shininess: 40,
      specular: 0x333333});
  grp.add(new THREE.Mesh(tubeGeometry(A.r1, n, s.radius, s.closed, c1), mat));
  grp.add(new THREE.Mesh(tubeGeometry(A.r2, n, s.radius, s.closed, c2), mat));
  var axg = new THREE.BufferGeometry();
  axg.setAttribute('position', new THREE.BufferAttribute(ax, 3));
  // the axis lies where the tubes touch, inside them: drawn over them
  var axis = new THREE.Line(axg, new THREE.LineBasicMaterial({color: 0xe00000, depthTest: false}));
  axis.renderOrder = 1;
  axis.visible = $('axis').checked; axis.name = 'axis';
  grp.add(axis);
  three.scene.add(grp);
  three.group = grp;
  // fit the camera to the first solution of a branch; later ones keep the view
  if (three.fitted !== br) {
    var bb = new THREE.Box3().setFromBufferAttribute(new THREE.BufferAttribute(A.r1, 3));
    var ctr = bb.getCenter(new THREE.Vector3()),
        rad = bb.getSize(new THREE.Vector3()).length() / 2 + s.radius;
    // look along the direction of least extent (a flat knot seen from above)
    var sz = bb.getSize(new THREE.Vector3()), dir = new THREE.Vector3(0, 0, 1);
    if (sz.x <= sz.y && sz.x <= sz.z) dir.set(1, 0, 0); else if (sz.y <= sz.z) dir.set(0, 1, 0);
    var dist = rad / Math.sin(THREE.MathUtils ? THREE.MathUtils.degToRad(15) : 15 * Math.PI / 180);
    three.camera.position.copy(ctr).add(dir.multiplyScalar(dist));
    three.camera.up.set(dir.z ? 0 : 0, dir.z ? 1 : 0, dir.z ? 0 : 1);
    three.camera.near = dist / 100; three.camera.far = dist * 10;
    three.camera.updateProjectionMatrix();
    three.controls.target.copy(ctr);
    three.controls.update();
    three.fitted = br;
  }
  drawColorbar(cm);
  three.renderer.render(three.scene, three.camera);
  return cm;
}
function cameraMatrix() {
  three.camera.updateMatrixWorld();
  var M = new THREE.Matrix4().multiplyMatrices(three.camera.projectionMatrix,
      three.camera.matrixWorldInverse);
  return Array.prototype.slice.call(M.elements);
}

// ---------------------------------------------------------------- selection
function select(bi, si) {
  var br = run.branches[bi], s = br.sols[si];
  cur.b = bi; cur.s = si;
  $('branch').value = String(bi);
  $('slider').max = String(br.sols.length - 1);
  $('slider').value = String(si);
  $('slidertext').textContent = (si + 1) + ' of ' + br.sols.length + ' solutions on ' + br.name;
  var lines = ['branch ' + br.name + '   LAB ' + s.lab + '   ' + s.ty + '   PT ' + s.pt];
  lines.push(run.columns.slice(0, 4).map(function (c) { return c + ' = ' + fmt(column(br,
      c)[s.row]); }).join('   '));
  var info = {branch: br.name, lab: s.lab, ty: s.ty, pt: s.pt, has3d: !!s.n};
  run.columns.forEach(function (c) { info[c] = column(br, c)[s.row]; });
  if (s.a) {
    lines.push('companion knot (braid axis): ' + s.a.knot + '   Lk = ' + fmt(s.a.Lk) + '  (Tw '
        + fmt(s.a.Tw) +
               ', Wr ' + fmt(s.a.Wr) + ')');
    lines.push('tubes ' + (s.a.noverlap > 0 ? 'OVERLAP' : 'do not overlap')
        + ': min distance / Delta = ' +
               fmt(s.a.dmin) + '   pressure ' + fmt(s.a.pmin) + ' .. ' + fmt(Math.max(s.a.pmax1,
                   s.a.pmax2)));
    for (var k in s.a) info[k] = s.a[k];
  }
  if (s.n && three) {
    var t0 = performance.now();
    var cm = show3d(br, s);
    window.cableView.timing.show3d = performance.now() - t0;
    info.plo = cm.lo; info.phi = cm.hi;
  } else if (!s.n) {
    lines.push('(no 3-D shape: ' + (s.why || 'not a braid solution') + ')');
  }
  $('info').textContent = lines.join('\n');
  window.cableView.info = info;
  drawDiagram();
}
window.cableView.select = select;
window.cableView.camera = function () { return cameraMatrix(); };
window.cableView.axisVisible = function () {
  return !!(three && three.group && three.group.getObjectByName('axis').visible);
};
window.cableView.findLabel = function (name, lab) {
  for (var b = 0; b < run.branches.length; b++)
    if (run.branches[b].name === name)
      for (var s = 0; s < run.branches[b].sols.length;
          s++) if (run.branches[b].sols[s].lab === lab) return [b, s];
  return null;
};

function showRun(r) {
  run = r;
  cur.b = -1; cur.s = -1;
  if (three) three.fitted = null;
  ['xcol', 'ycol'].forEach(function (id) {
    var sel = $(id);
    sel.innerHTML = '';
    run.columns.forEach(function (c) { var o = document.createElement('option');
        o.value = o.textContent = c; sel.appendChild(o); });
  });
  view.x = run.xdefault; view.y = run.ydefault;
  $('xcol').value = view.x; $('ycol').value = view.y;
  var bs = $('branch');
  bs.innerHTML = '';
  run.branches.forEach(function (br, i) {
    var o = document.createElement('option'); o.value = String(i);
        o.textContent = br.name + ' (' + br.sols.length + ')';
    bs.appendChild(o);
  });
  view.box = dataBox();
  // (select() draws the diagram; without a selection it is drawn at the end)
  // a link to a label: view.html#BRANCH/LAB (e.g. #mode2/19)
  var hash = decodeURIComponent((window.location.hash || '').slice(1)).split('/');
  if (hash.length === 2) {
    var where = window.cableView.findLabel(hash[0], Number(hash[1]));
    if (where) { select(where[0], where[1]); return; }
  }
  if (run.select !== undefined)
    for (var b0 = 0; b0 < run.branches.length; b0++)
      for (var s0 = 0; s0 < run.branches[b0].sols.length; s0++)
        if (run.branches[b0].sols[s0].lab === run.select) { select(b0, s0); return; }
  // start at the first UZ point (a scene's chosen T), else the first solution with a 3-D shape
  for (var b1 = 0; b1 < run.branches.length; b1++)
    for (var s1 = 0; s1 < run.branches[b1].sols.length; s1++)
      if (run.branches[b1].sols[s1].n && run.branches[b1].sols[s1].ty === 'UZ') { select(b1,
          s1); return; }
  for (var b = 0; b < run.branches.length; b++)
    for (var s = 0; s < run.branches[b].sols.length; s++)
      if (run.branches[b].sols[s].n) { select(b, s); return; }
  drawDiagram();
  $('info').textContent = 'no labelled solution with a 3-D shape';
}

function showAtlas() {
  var box = $('tasks');
  box.style.display = 'block';
  var t = document.createElement('table'), head = document.createElement('tr');
  var cols = DATA.columns;
  ['task'].concat(cols).forEach(function (c) { var th = document.createElement('th');
      th.textContent = c; head.appendChild(th); });
  t.appendChild(head);
  DATA.tasks.forEach(function (task, ti) {
    task.rows.forEach(function (row, ri) {
      var tr = document.createElement('tr');
      tr.className = 'task' + (task.run ? '' : ' nofiles');
      tr.setAttribute('data-task', ti);
      var td = document.createElement('td');
      td.textContent = ri === 0 ? task.name + (task.run ? '' : ' (no b./s. files)') : '';
      tr.appendChild(td);
      cols.forEach(function (c) { var d = document.createElement('td');
          d.textContent = fmt(row[c]); tr.appendChild(d); });
      tr.onclick = function () { openTask(ti); };
      t.appendChild(tr);
    });
  });
  box.appendChild(t);
  var first = -1;
  DATA.tasks.forEach(function (task, ti) { if (first < 0 && task.run) first = ti; });
  if (first >= 0) openTask(first);
  else $('info').textContent = 'none of the ' + DATA.tasks.length
      + ' tasks has its b./s. files here';
}
function openTask(ti) {
  var task = DATA.tasks[ti];
  Array.prototype.forEach.call(document.querySelectorAll('#tasks tr.task'), function (tr) {
    tr.classList.toggle('current', Number(tr.getAttribute('data-task')) === ti);
  });
  window.cableView.task = task.name;
  $('subtitle').textContent = 'task ' + task.name;
  if (!task.run) { $('info').textContent = task.name + ': ' + task.why; return; }
  showRun(task.run);
}
window.cableView.openTask = function (name) {
  for (var i = 0; i < DATA.tasks.length; i++) if (DATA.tasks[i].name === name) { openTask(i);
      return true; }
  return false;
};

function start() {
  var T = window.cableView.timing = {start: performance.now()};
  $('title').textContent = document.title = DATA.title;
  setupDiagram();
  try {
    setup3d();
    T.webgl = performance.now();
  } catch (e) {
    window.cableView.error = 'WebGL: ' + e.message;
    $('view3d').textContent = 'no 3-D view: this browser gives no WebGL (' + e.message + ')';
  }
  $('axis').onchange = function () {
    if (three && three.group) {
      three.group.getObjectByName('axis').visible = this.checked;
      three.renderer.render(three.scene, three.camera);
    }
  };
  $('branch').onchange = function () {
    var b = Number(this.value);
    if (run.branches[b].sols.length) select(b, 0);
  };
  $('slider').oninput = function () { if (cur.b >= 0) select(cur.b, Number(this.value)); };
  if (DATA.kind === 'atlas') showAtlas(); else showRun(DATA);
  T.shown = performance.now();
  window.cableView.ready = true;
  window.cableView.readyAt = performance.now();
}
if (document.readyState === 'loading') document.addEventListener('DOMContentLoaded', start);
    else start();
})();
"""
