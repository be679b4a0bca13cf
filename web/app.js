// The page: points in, the engine (in a Web Worker) run on them, the result drawn on a
// canvas that zooms and pans, and the command line's writers for the downloads.

const GPL = {
  'hnn-crust-sgp16': 'HNN-Crust (SGP 2016)',
  fitconnect: 'FitConnect (CGF 2018)',
  stretchdenoise: 'StretchDenoise (2018/19)',
};

// The bundled point sets (copied next to the page by web/build.sh). `source`: the GPL-3.0
// repository of Stefan Ohrhallinger's that a real set comes from; `readme`: the README
// beside it that says so.
const EXAMPLES = [
  { name: 'bean', file: 'bean.txt', what: 'bean: 150 points on one closed curve' },
  { name: 'mushroom', file: 'mushroom.p2d', what: 'mushroom: 59 points, very sparse', source: 'hnn-crust-sgp16', yDown: true },
  { name: 'crocodile', file: 'crocodile-conf.p2d', what: 'crocodile: 129 points, several curves', source: 'hnn-crust-sgp16', yDown: true },
  { name: 'ventilator', file: 'ventilator.p2d', what: 'ventilator: 194 points, nested curves', source: 'hnn-crust-sgp16', yDown: true, readme: 'README-tests-data.md' },
  { name: 'apple', file: 'apple_2percent_noise.txt', what: 'apple: 170 points, 2% noise', source: 'fitconnect' },
  { name: 'circle', file: 'Circle0.txt', what: 'circle: 248 stair-stepped points', source: 'stretchdenoise' },
  { name: 'stair', file: 'stair.xy', what: 'stair: 160 points on an open curve', source: 'stretchdenoise', readme: 'README-tests-data.md' },
  { name: 'family', file: 'family.p2d', what: 'family: 9990 points, a raster boundary', source: 'stretchdenoise', yDown: true, readme: 'README-tests-data.md' },
];

const $ = (id) => document.getElementById(id);
const canvas = $('canvas');
const summary = $('summary');
const progress = $('progress');

// ---- the engine's thread -----------------------------------------------------------------

const worker = new Worker(new URL('worker.js', import.meta.url), { type: 'module' });
const pending = new Map();
let nextId = 1;

function ask(message, transfer = [], onProgress = null) {
  const id = nextId++;
  return new Promise((resolve, reject) => {
    pending.set(id, { resolve, reject, onProgress });
    worker.postMessage({ ...message, id }, transfer);
  });
}

worker.onmessage = ({ data }) => {
  if (data.type === 'ready') return;
  const request = pending.get(data.id);
  if (!request) {
    if (data.type === 'error') showError(data.message);
    return;
  }
  if (data.type === 'progress') {
    if (request.onProgress) request.onProgress(data);
    return;
  }
  pending.delete(data.id);
  if (data.type === 'error') request.reject(new Error(data.message));
  else request.resolve(data);
};
worker.onerror = (event) => showError(`the engine's thread failed: ${event.message}`);

// ---- state -------------------------------------------------------------------------------

let coords = new Float64Array(0); // the points, x and y in turn
let sourceName = 'points';
let result = null; // the last reconstruction: { coords, drawing, summary, warnings, ms }
const view = { cx: 0, cy: 0, scale: 1 };
let viewMoved = false; // zoomed or panned by the user: a resize keeps the view then
let size = { width: 1, height: 1 };

function choices() {
  return {
    algorithm: $('algorithm').value,
    medialAxis: $('medial-axis').value,
    peeling: $('peeling').checked,
    smooth: $('smooth').checked,
    thinning: $('thinning').checked,
    voronoi: $('layer-voronoi').checked || $('layer-labels').checked,
  };
}

function layers() {
  return {
    points: $('layer-points').checked,
    axis: $('layer-medial-axis').checked,
    delaunay: $('layer-delaunay').checked,
    voronoi: $('layer-voronoi').checked,
    labels: $('layer-labels').checked && $('algorithm').value === 'wdm',
    yDown: $('y-down').checked,
  };
}

// ---- running the engine: one request at a time, the latest points next ------------------

// From this many points on, a reconstruction shows its progress from the start.
const LARGE = 50000;
let running = false;
let dirty = false;
let runs = 0;

function schedule() {
  dirty = true;
  if (!running) pump();
}

async function pump() {
  running = true;
  while (dirty) {
    dirty = false;
    const snapshot = coords.slice();
    const n = snapshot.length / 2;
    summary.dataset.state = 'working';
    const started = performance.now();
    const phases = [];
    // Progress for a large input from the start; for a small one only if it is slow (not
    // at every step of a drag).
    const large = n >= LARGE;
    const onProgress = ({ phase, ms }) => {
      phases.push(`${phase} ${ms.toFixed(0)} ms`);
      if (large || performance.now() - started > 300) {
        showProgress(`reconstructing ${n} points…\n${phases.join('\n')}`);
      }
    };
    const timer = setTimeout(() => showProgress(`reconstructing ${n} points…`), large ? 0 : 300);
    try {
      const answer = await ask({ type: 'run', coords: snapshot.slice(), choices: choices() }, [], onProgress);
      result = { coords: snapshot, ...answer };
      runs += 1;
      if (!dirty) showSummary();
    } catch (e) {
      dirty = false;
      showError(e.message);
    } finally {
      clearTimeout(timer);
      hideProgress();
    }
    draw();
  }
  running = false;
}

function showProgress(text) {
  progress.textContent = text;
  progress.hidden = false;
}

function hideProgress() {
  progress.hidden = true;
}

function showSummary() {
  summary.replaceChildren();
  const counts = document.createElement('span');
  counts.className = 'counts';
  counts.textContent = result.summary;
  const time = document.createElement('span');
  time.className = 'note';
  time.textContent = ` (${result.ms.toFixed(0)} ms)`;
  summary.append(counts, time);
  if (result.warnings.length > 0) {
    const list = document.createElement('ul');
    for (const warning of result.warnings) {
      const item = document.createElement('li');
      item.className = 'warning';
      item.textContent = `warning: ${warning}`;
      list.append(item);
    }
    summary.append(list);
  }
  summary.dataset.state = 'done';
  summary.dataset.runs = String(runs);
  summary.dataset.points = String(result.coords.length / 2);
}

function showError(message) {
  summary.replaceChildren();
  const line = document.createElement('p');
  line.className = 'error';
  line.textContent = message;
  summary.append(line);
  summary.dataset.state = 'error';
}

// ---- points in ---------------------------------------------------------------------------

function setPoints(newCoords, name, yDown) {
  coords = newCoords;
  sourceName = name;
  $('y-down').checked = yDown;
  result = null;
  fit();
  schedule();
}

async function loadBytes(name, bytes, yDown = false) {
  summary.dataset.state = 'working';
  showProgress(`reading ${name} (${bytes.byteLength} bytes)…`);
  try {
    const { coords: read } = await ask({ type: 'parse', name, bytes }, [bytes]);
    setPoints(read, name, yDown);
  } catch (e) {
    showError(e.message);
  } finally {
    hideProgress();
  }
}

async function loadFile(file) {
  $('example').value = '';
  showLicence(null);
  await loadBytes(file.name, await file.arrayBuffer());
}

async function loadExample(name) {
  const example = EXAMPLES.find((e) => e.name === name);
  if (!example) {
    showError(`no example named ${JSON.stringify(name)}: ${EXAMPLES.map((e) => e.name).join(', ')}`);
    return;
  }
  $('example').value = name;
  showLicence(example);
  const response = await fetch(`examples/${example.file}`);
  if (!response.ok) {
    showError(`examples/${example.file}: ${response.status} ${response.statusText}`);
    return;
  }
  await loadBytes(example.file, await response.arrayBuffer(), Boolean(example.yDown));
}

function showLicence(example) {
  const note = $('licence');
  note.replaceChildren();
  if (!example) return;
  if (!example.source) {
    note.textContent = `${example.file}: made for wdm-crust, MIT OR Apache-2.0 like the code.`;
    return;
  }
  const link = (href, text) => {
    const a = document.createElement('a');
    a.href = href;
    a.textContent = text;
    return a;
  };
  note.append(
    `${example.file}: data from Stefan Ohrhallinger's ${example.source} repository (${GPL[example.source]}), `
    + 'licensed GPL-3.0 (the data file only, not the code): ',
    link('examples/GPL-3.0.txt', 'licence text'),
    ', ',
    link(`examples/${example.readme || 'README.md'}`, 'origin'),
    '.',
  );
}

// ---- the view ----------------------------------------------------------------------------

function toScreen(x, y) {
  const sy = $('y-down').checked ? (y - view.cy) : (view.cy - y);
  return [(x - view.cx) * view.scale + size.width / 2, sy * view.scale + size.height / 2];
}

function toWorld(sx, sy) {
  const dy = (sy - size.height / 2) / view.scale;
  return [(sx - size.width / 2) / view.scale + view.cx, $('y-down').checked ? view.cy + dy : view.cy - dy];
}

function fit() {
  viewMoved = false;
  let [x0, y0, x1, y1] = [Infinity, Infinity, -Infinity, -Infinity];
  for (let i = 0; i < coords.length; i += 2) {
    const [x, y] = [coords[i], coords[i + 1]];
    if (!Number.isFinite(x) || !Number.isFinite(y)) continue;
    x0 = Math.min(x0, x); x1 = Math.max(x1, x);
    y0 = Math.min(y0, y); y1 = Math.max(y1, y);
  }
  if (x0 > x1) {
    Object.assign(view, { cx: 0, cy: 0, scale: Math.min(size.width, size.height) / 2 });
  } else {
    const extent = Math.max(x1 - x0, y1 - y0) || Math.max(Math.abs(x0), Math.abs(y0), 1);
    const scale = 0.9 * Math.min(size.width / Math.max(x1 - x0, extent * 1e-9), size.height / Math.max(y1 - y0, extent * 1e-9));
    Object.assign(view, { cx: (x0 + x1) / 2, cy: (y0 + y1) / 2, scale: Math.min(scale, 0.9 * Math.min(size.width, size.height) / extent * 1e6) });
  }
  draw();
}

function resize() {
  const box = canvas.getBoundingClientRect();
  const ratio = window.devicePixelRatio || 1;
  size = { width: Math.max(box.width, 1), height: Math.max(box.height, 1) };
  canvas.width = Math.round(size.width * ratio);
  canvas.height = Math.round(size.height * ratio);
  if (viewMoved) draw();
  else fit();
}

// Canvas coordinates far outside the picture are clamped (a Voronoi vertex can be very far).
const clamp = (v) => Math.max(-1e7, Math.min(1e7, v));

function draw() {
  const ctx = canvas.getContext('2d');
  const ratio = canvas.width / size.width;
  ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
  ctx.fillStyle = '#ffffff';
  ctx.fillRect(0, 0, size.width, size.height);
  const show = layers();
  const n = coords.length / 2;
  // Dense points go under the curves, which they would hide; sparse ones on top.
  const dense = n > 2000;
  if (result && !dense) drawResult(ctx, show);
  if (show.points && dense) {
    // Squares: many thousand arcs would hold up the page for a second.
    ctx.fillStyle = '#777777';
    for (let i = 0; i < coords.length; i += 2) {
      const [sx, sy] = toScreen(coords[i], coords[i + 1]);
      if (sx < -2 || sy < -2 || sx > size.width + 2 || sy > size.height + 2) continue;
      ctx.fillRect(sx - 1, sy - 1, 2, 2);
    }
  } else if (show.points) {
    ctx.fillStyle = '#111111';
    ctx.beginPath();
    for (let i = 0; i < coords.length; i += 2) {
      const [sx, sy] = toScreen(coords[i], coords[i + 1]);
      if (sx < -5 || sy < -5 || sx > size.width + 5 || sy > size.height + 5) continue;
      ctx.moveTo(sx + 2.6, sy);
      ctx.arc(sx, sy, 2.6, 0, 2 * Math.PI);
    }
    ctx.fill();
  }
  if (result && dense) drawResult(ctx, show);
}

function segments(ctx, colour, width, each) {
  ctx.strokeStyle = colour;
  ctx.lineWidth = width;
  ctx.beginPath();
  const line = (a, b) => {
    if (![...a, ...b].every(Number.isFinite)) return;
    ctx.moveTo(clamp(a[0]), clamp(a[1]));
    ctx.lineTo(clamp(b[0]), clamp(b[1]));
  };
  each(line);
  ctx.stroke();
}

function rings(ctx, colour, radius, width, indices, at) {
  ctx.strokeStyle = colour;
  ctx.lineWidth = width;
  ctx.beginPath();
  for (const i of indices) {
    const [sx, sy] = at(i);
    ctx.moveTo(sx + radius, sy);
    ctx.arc(sx, sy, radius, 0, 2 * Math.PI);
  }
  ctx.stroke();
}

function drawResult(ctx, show) {
  const d = result.drawing;
  const pts = result.coords;
  const point = (i) => toScreen(pts[2 * i], pts[2 * i + 1]);
  const diagonal = Math.hypot(size.width, size.height);
  // Round joins are costly on paths of many thousand vertices.
  const dense = pts.length / 2 > 2000;
  ctx.lineCap = dense ? 'butt' : 'round';
  ctx.lineJoin = dense ? 'bevel' : 'round';
  if (show.delaunay) {
    segments(ctx, '#c8c8c8', 0.8, (line) => {
      for (let k = 0; k < d.delaunayEdges.length; k += 2) line(point(d.delaunayEdges[k]), point(d.delaunayEdges[k + 1]));
    });
  }
  const vertex = (v) => toScreen(d.voronoiVertices[2 * v], d.voronoiVertices[2 * v + 1]);
  if (show.voronoi) {
    segments(ctx, '#8fb9dc', 0.9, (line) => {
      for (let k = 0; k < d.voronoiEdges.length; k += 2) line(vertex(d.voronoiEdges[k]), vertex(d.voronoiEdges[k + 1]));
      const reach = (from, dx, dy) => {
        const length = Math.hypot(dx, dy) || 1;
        const far = Math.hypot(from[0] - size.width / 2, from[1] - size.height / 2) + diagonal;
        return [from[0] + (dx / length) * far, from[1] + (dy / length) * far];
      };
      const flip = $('y-down').checked ? 1 : -1;
      for (let k = 0; k < d.voronoiRays.length; k += 3) {
        const from = vertex(d.voronoiRays[k]);
        line(from, reach(from, d.voronoiRays[k + 1], flip * d.voronoiRays[k + 2]));
      }
      for (let k = 0; k < d.voronoiBisectors.length; k += 2) {
        const [a, b] = [point(d.voronoiBisectors[k]), point(d.voronoiBisectors[k + 1])];
        const mid = [(a[0] + b[0]) / 2, (a[1] + b[1]) / 2];
        const [dx, dy] = [b[1] - a[1], a[0] - b[0]];
        line(reach(mid, -dx, -dy), reach(mid, dx, dy));
      }
    });
  }
  if (show.labels && d.labels.length > 0) {
    for (const [label, colour] of [[0, '#1f77b4'], [1, '#ff7f0e']]) {
      ctx.fillStyle = colour;
      ctx.beginPath();
      for (let v = 0; v < d.labels.length; v += 1) {
        if (d.labels[v] !== label) continue;
        const [sx, sy] = vertex(v);
        if (sx < -5 || sy < -5 || sx > size.width + 5 || sy > size.height + 5) continue;
        ctx.moveTo(sx + 2, sy);
        ctx.arc(sx, sy, 2, 0, 2 * Math.PI);
      }
      ctx.fill();
    }
  }
  if (show.axis) {
    const axis = (v) => toScreen(d.axisVertices[2 * v], d.axisVertices[2 * v + 1]);
    segments(ctx, '#2ca02c', 1.4, (line) => {
      for (let k = 0; k < d.axisEdges.length; k += 2) line(axis(d.axisEdges[k]), axis(d.axisEdges[k + 1]));
    });
  }
  for (const [closed, colour] of [[1, '#d62728'], [0, '#7b3fb5']]) {
    ctx.strokeStyle = colour;
    ctx.lineWidth = 2.2;
    ctx.beginPath();
    for (let c = 0; c < d.curveClosed.length; c += 1) {
      if (d.curveClosed[c] !== closed) continue;
      for (let k = d.curveOffsets[c]; k < d.curveOffsets[c + 1]; k += 1) {
        const [sx, sy] = toScreen(d.curveCoords[2 * k], d.curveCoords[2 * k + 1]);
        if (k === d.curveOffsets[c]) ctx.moveTo(clamp(sx), clamp(sy));
        else ctx.lineTo(clamp(sx), clamp(sy));
      }
      if (closed) ctx.closePath();
    }
    ctx.stroke();
  }
  rings(ctx, '#8c8c8c', 4, 1.2, d.unassigned, point);
  rings(ctx, '#e6a100', 8, 2, d.warningPoints, point);
}

// ---- editing, zooming, panning -----------------------------------------------------------

function nearestPoint(sx, sy, within) {
  let best = -1;
  let bestDistance = within * within;
  for (let i = 0; i < coords.length / 2; i += 1) {
    const [px, py] = toScreen(coords[2 * i], coords[2 * i + 1]);
    const distance = (px - sx) ** 2 + (py - sy) ** 2;
    if (distance <= bestDistance) {
      best = i;
      bestDistance = distance;
    }
  }
  return best;
}

function withPoint(x, y) {
  const grown = new Float64Array(coords.length + 2);
  grown.set(coords);
  grown[coords.length] = x;
  grown[coords.length + 1] = y;
  return grown;
}

function withoutPoint(i) {
  const shrunk = new Float64Array(coords.length - 2);
  shrunk.set(coords.subarray(0, 2 * i));
  shrunk.set(coords.subarray(2 * i + 2), 2 * i);
  return shrunk;
}

let gesture = null;

canvas.addEventListener('pointerdown', (event) => {
  const [sx, sy] = [event.offsetX, event.offsetY];
  const hit = nearestPoint(sx, sy, 7);
  gesture = { hit, start: [sx, sy], last: [sx, sy], moved: false, shift: event.shiftKey };
  canvas.setPointerCapture(event.pointerId);
});

canvas.addEventListener('pointermove', (event) => {
  if (!gesture) return;
  const [sx, sy] = [event.offsetX, event.offsetY];
  if (Math.hypot(sx - gesture.start[0], sy - gesture.start[1]) > 3) gesture.moved = true;
  if (!gesture.moved) return;
  if (gesture.hit >= 0 && !gesture.shift) {
    const [x, y] = toWorld(sx, sy);
    coords[2 * gesture.hit] = x;
    coords[2 * gesture.hit + 1] = y;
    draw();
    schedule();
  } else {
    viewMoved = true;
    const [dx, dy] = [sx - gesture.last[0], sy - gesture.last[1]];
    view.cx -= dx / view.scale;
    view.cy += ($('y-down').checked ? -dy : dy) / view.scale;
    draw();
  }
  gesture.last = [sx, sy];
});

canvas.addEventListener('pointerup', (event) => {
  if (!gesture) return;
  const { hit, moved, shift } = gesture;
  gesture = null;
  if (moved) return;
  if (hit >= 0 && shift) {
    coords = withoutPoint(hit);
  } else if (hit < 0) {
    const [x, y] = toWorld(event.offsetX, event.offsetY);
    coords = withPoint(x, y);
  } else {
    return;
  }
  draw();
  schedule();
});

canvas.addEventListener('wheel', (event) => {
  event.preventDefault();
  viewMoved = true;
  const [sx, sy] = [event.offsetX, event.offsetY];
  const [x, y] = toWorld(sx, sy);
  view.scale *= Math.exp(-event.deltaY * 0.0015);
  const [x2, y2] = toWorld(sx, sy);
  view.cx += x - x2;
  view.cy += y - y2;
  draw();
}, { passive: false });

const viewBox = $('view');
viewBox.addEventListener('dragover', (event) => {
  event.preventDefault();
  viewBox.classList.add('dropping');
});
viewBox.addEventListener('dragleave', () => viewBox.classList.remove('dropping'));
viewBox.addEventListener('drop', (event) => {
  event.preventDefault();
  viewBox.classList.remove('dropping');
  const file = event.dataTransfer.files[0];
  if (file) loadFile(file);
});

// ---- downloads ---------------------------------------------------------------------------

async function exportText(format) {
  const show = layers();
  const { text } = await ask({
    type: 'export', format,
    layers: { delaunay: show.delaunay, voronoi: show.voronoi, labels: show.labels, yDown: show.yDown },
  });
  return text;
}

async function download(format) {
  try {
    const text = await exportText(format);
    const type = { svg: 'image/svg+xml', geojson: 'application/geo+json', json: 'application/json' }[format];
    const url = URL.createObjectURL(new Blob([text], { type }));
    const a = document.createElement('a');
    a.href = url;
    a.download = `${sourceName.replace(/\.[^.]*$/, '') || 'points'}.${format}`;
    document.body.append(a);
    a.click();
    a.remove();
    setTimeout(() => URL.revokeObjectURL(url), 10000);
  } catch (e) {
    showError(e.message);
  }
}

// ---- controls ----------------------------------------------------------------------------

function syncControls() {
  const wdm = $('algorithm').value === 'wdm';
  // What the baselines do not do, as the command line refuses it for them.
  for (const id of ['medial-axis', 'peeling', 'thinning', 'layer-labels']) $(id).disabled = !wdm;
}

for (const example of EXAMPLES) {
  const option = document.createElement('option');
  option.value = example.name;
  option.textContent = example.what;
  $('example').append(option);
}
const none = document.createElement('option');
none.value = '';
none.textContent = '(a file of yours)';
$('example').append(none);

$('example').addEventListener('change', () => {
  if ($('example').value) loadExample($('example').value);
});
$('file').addEventListener('change', () => {
  const file = $('file').files[0];
  if (file) loadFile(file);
});
$('clear').addEventListener('click', () => setPoints(new Float64Array(0), 'points', $('y-down').checked));
for (const id of ['algorithm', 'medial-axis', 'peeling', 'smooth', 'thinning', 'layer-voronoi', 'layer-labels']) {
  $(id).addEventListener('change', () => {
    syncControls();
    schedule();
  });
}
for (const id of ['layer-points', 'layer-medial-axis', 'layer-delaunay', 'y-down']) {
  $(id).addEventListener('change', draw);
}
$('fit').addEventListener('click', fit);
for (const format of ['svg', 'geojson', 'json']) {
  $(`download-${format}`).addEventListener('click', () => download(format));
}
new ResizeObserver(resize).observe(canvas);

// The command line's options, as URL parameters: ?example=bean&algorithm=crust&smooth=1
// &no-peeling=1&no-thinning=1&medial-axis=raw&show=delaunay,voronoi,labels
const params = new URLSearchParams(window.location.search);
if (params.has('algorithm')) $('algorithm').value = params.get('algorithm');
if (params.has('medial-axis')) $('medial-axis').value = params.get('medial-axis');
if (params.get('no-peeling') === '1') $('peeling').checked = false;
if (params.get('smooth') === '1') $('smooth').checked = true;
if (params.get('no-thinning') === '1') $('thinning').checked = false;
for (const layer of (params.get('show') || '').split(',').filter(Boolean)) {
  const box = $(`layer-${layer}`);
  if (box) box.checked = true;
}
syncControls();

// For scripts (the browser test): the downloads' text, the points, where a point is drawn.
window.wdmPage = {
  exportText,
  points: () => coords.slice(),
  // The result shown is that of the points as they are, and nothing is left to run.
  idle: () => !running && !dirty && result !== null && result.coords.length === coords.length
    && result.coords.every((v, i) => Object.is(v, coords[i])),
  screenOf: (i) => {
    const box = canvas.getBoundingClientRect();
    const [sx, sy] = toScreen(coords[2 * i], coords[2 * i + 1]);
    return [box.left + sx, box.top + sy];
  },
};

resize();
loadExample(params.get('example') || 'bean');
