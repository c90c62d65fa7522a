// The page of `unidyn report`: the model and its equations, plots of the run, and the run in 3-D.
// Everything it shows is in the page's JSON (id "unidyn-data", written by src/report/report_data):
// nothing is fetched. Opened with #selftest it checks itself and writes what it found into
// <pre id="selftest"> (the browser tests read it); with #t=T it shows the run paused at time T.
import {
  AmbientLight,
  ArrowHelper,
  AxesHelper,
  BoxGeometry,
  BufferGeometry,
  Color,
  ConeGeometry,
  CylinderGeometry,
  DirectionalLight,
  DoubleSide,
  Float32BufferAttribute,
  GridHelper,
  Group,
  Line,
  LineBasicMaterial,
  Matrix4,
  Mesh,
  MeshStandardMaterial,
  PerspectiveCamera,
  PlaneGeometry,
  Quaternion,
  Scene,
  SphereGeometry,
  Vector3,
  WebGLRenderer,
} from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import uPlot from 'uplot';
import 'uplot/dist/uPlot.min.css';
import katex from 'katex';
import './report.css';

// Errors and console errors, for #selftest.
const errors = [];
window.addEventListener('error', (e) => errors.push(String(e.message)));
const consoleError = console.error;
console.error = (...args) => {
  errors.push(args.map(String).join(' '));
  consoleError(...args);
};

const data = JSON.parse(document.getElementById('unidyn-data').textContent);
const run = data.run;
// each column: little-endian 32-bit floats in base64 (report_page.cpp); a value that is not
// finite (NaN, an infinity, past the float's range) is a gap, counted: the plots say so
const notFinite = {};
for (const [name, text] of Object.entries(run.columns)) {
  const bytes = Uint8Array.from(atob(text), (c) => c.charCodeAt(0));
  let count = 0;
  run.columns[name] = Array.from(new Float32Array(bytes.buffer), (v) => {
    if (Number.isFinite(v)) return v;
    ++count;
    return null;
  });
  if (count) notFinite[name] = count;
}
const time = run.columns.t;
const palette = ['#1f77b4', '#d62728', '#2ca02c', '#ff7f0e', '#9467bd', '#8c564b', '#e377c2',
  '#17becf', '#7f7f7f', '#bcbd22'];

// A DOM element with attributes and children.
function element(tag, attributes = {}, ...children) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attributes)) e.setAttribute(k, v);
  for (const c of children) e.append(c);
  return e;
}

const app = document.getElementById('app');
// The page's sections, in this order: the motion first, the model last.
app.append(element('h1', {}, data.model.name));
if (data.model.reference) app.append(element('p', { class: 'reference' }, data.model.reference));
const sections = {};
for (const [id, title] of [['motion', 'Motion'], ['run', 'Run'], ['phase', 'Phase portraits'],
  ['equations', 'Equations of motion'], ['equilibria', 'Equilibria'],
  ['modes', 'Linearisation and modes'], ['model', 'Model']]) {
  sections[id] = element('section', { id }, element('h2', {}, title));
  app.append(sections[id]);
}

// --- The model: parameters, coordinates ---------------------------------------------------------
{
  const s = sections.model;
  const table = element('table', { class: 'parameters' });
  table.append(element('tr', {}, element('th', {}, 'parameter'), element('th', {}, 'value')));
  for (const [name, value] of data.model.parameters) {
    table.append(element('tr', {}, element('td', {}, name), element('td', {}, String(value))));
  }
  s.append(table);
  s.append(element('p', {}, 'Coordinates: ' + data.model.coordinates.join(', ')));
}

// --- The equations (LaTeX from `unidyn derive --format latex`, as MathML) ----------------------
// The align environment of a LaTeX document as KaTeX's aligned, without labels and \nonumber.
function displayable(tex) {
  return tex
    .replace(/\\label\{[^}]*\}/g, '')
    .replace(/\\\[|\\\]/g, '')
    .replace(/\\nonumber/g, '')
    .replace(/\\begin\{align\}/g, '\\begin{aligned}')
    .replace(/\\end\{align\}/g, '\\end{aligned}');
}
// LaTeX as a block of MathML, typeset after the motion's first picture (renderMath).
const mathJobs = [];
function mathBlock(tex) {
  const div = element('div', { class: 'math' });
  mathJobs.push(() => {
    div.innerHTML = katex.renderToString(displayable(tex), {
      displayMode: true, output: 'mathml', throwOnError: false, strict: 'ignore',
    });
  });
  return div;
}
function renderMath() {
  for (const job of mathJobs.splice(0)) job();
}
{
  const s = sections.equations;
  for (const block of data.equations.latex) s.append(mathBlock(block));
  for (const note of data.equations.notes) s.append(element('p', { class: 'note' }, note));
  if (data.equations.check) s.append(element('pre', {}, data.equations.check));
}

// --- The equilibria (`unidyn equilibria`): each with its verdict -------------------------------
{
  const s = sections.equilibria;
  const found = data.equilibria;
  if (found.not_sought !== undefined) {
    s.append(element('p', { class: 'note' }, `Not sought: ${found.not_sought}`));
  } else {
    s.append(element('p', {}, `${found.items.length} found from ${found.starts} starts` +
      (found.singular ? `; ${found.singular} starts ended where the equations are singular` : '') +
      (found.moving ? `; ${found.moving} balance points move` : '') +
      '. Coordinates in the order: ' + data.model.coordinates.join(', ') + '.'));
    const table = element('table', { class: 'parameters' });
    table.append(element('tr', {}, element('th', {}, '#'), element('th', {}, 'coordinates'),
      element('th', {}, 'stability'), element('th', {}, 'eigenvalues of the linearisation'),
      element('th', {}, 'potential')));
    const shown = found.items.slice(0, 12);
    shown.forEach((e, k) => {
      const potential = e.potential_minimum === null ? '' :
        e.potential_minimum ? 'strict minimum' : 'no minimum';
      table.append(element('tr', {}, element('td', {}, String(k + 1)),
        element('td', {}, e.coordinates.join(', ') +
          (e.continuum ? ` (on a ${e.continuum}-dimensional continuum)` : '')),
        element('td', { title: e.reason }, e.stability),
        element('td', { class: 'eigenvalues' }, e.eigenvalues.join(', ')),
        element('td', {}, potential)));
    });
    s.append(table);
    if (found.items.length > shown.length) {
      s.append(element('p', {}, `… and ${found.items.length - shown.length} more (unidyn equilibria lists every one)`));
    }
  }
}

// --- The linearisation about an operating point (`unidyn modes`): A, the modes, the verdict -----
{
  const s = sections.modes;
  const point = data.operating_point;
  if (point.none !== undefined) {
    s.append(element('p', { class: 'note' }, `No operating point: ${point.none}. ` +
      'unidyn report MODEL --at NAME=VALUE names one.'));
  } else if (point.multipliers !== undefined) {
    // a driven system's periodic motion (`unidyn modes` of a model whose equations depend on t)
    s.append(element('p', {}, `About ${point.label}: a periodic motion of period T = ` +
      `${point.period} s; x' = A(t) x over one period gives the monodromy matrix Φ, ` +
      'x(t0 + T) = Φ x(t0), whose eigenvalues are the Floquet multipliers (a perturbation is ' +
      'multiplied by μ each period).'));
    s.append(mathBlock(point.latex));
    const table = element('table', { class: 'parameters' });
    table.append(element('tr', {}, element('th', {}, 'multiplier μ'), element('th', {}, '|μ|'),
      element('th', {}, 'exponent log(μ)/T')));
    for (const m of point.multipliers) {
      table.append(element('tr', {}, element('td', { class: 'eigenvalues' }, m.multiplier),
        element('td', {}, m.modulus === null ? '' : m.modulus.toPrecision(6)),
        element('td', { class: 'eigenvalues' }, m.exponent)));
    }
    s.append(table);
    s.append(element('p', {}, `${point.stability}: ${point.reason}`));
  } else {
    s.append(element('p', {}, `About ${point.label}: x' = A x, the independent coordinates and ` +
      'rates perturbed (ignorable coordinates dropped).'));
    s.append(mathBlock(point.latex));
    const table = element('table', { class: 'parameters' });
    table.append(element('tr', {}, element('th', {}, 'eigenvalue'),
      element('th', {}, 'natural frequency (rad/s)'), element('th', {}, 'damping ratio'),
      element('th', {}, 'shape (modulus, phase)')));
    for (const m of point.modes) {
      const shape = m.shape.map(([name, modulus, phase]) =>
        `${m.of_rates ? `der(${name})` : name}: ${modulus}` + (phase ? ` ∠${phase}°` : '')).join(', ');
      table.append(element('tr', {}, element('td', { class: 'eigenvalues' }, m.eigenvalue),
        element('td', {}, m.natural_frequency === null ? '' : m.natural_frequency.toPrecision(6)),
        element('td', {}, m.damping_ratio === null ? '' : m.damping_ratio.toPrecision(4)),
        element('td', {}, shape)));
    }
    s.append(table);
    s.append(element('p', {}, `${point.stability}: ${point.reason}`));
  }
}

// --- The run: its summary, events, plots --------------------------------------------------------
let cursorTime = time[0];
const charts = [];
const sync = uPlot.sync('unidyn');
// Events and phases as vertical lines, the animation's time as a dashed one.
function markers(u) {
  const ctx = u.ctx;
  const { top, height } = u.bbox;
  ctx.save();
  ctx.lineWidth = 1;
  for (const e of run.events) {
    const x = u.valToPos(e.t, 'x', true);
    ctx.strokeStyle = '#aa3300';
    ctx.beginPath();
    ctx.moveTo(x, top);
    ctx.lineTo(x, top + height);
    ctx.stroke();
  }
  const x = u.valToPos(cursorTime, 'x', true);
  ctx.strokeStyle = '#000';
  ctx.setLineDash([4, 4]);
  ctx.beginPath();
  ctx.moveTo(x, top);
  ctx.lineTo(x, top + height);
  ctx.stroke();
  ctx.restore();
}
// An axis tick: 4 significant digits, powers of ten where they are small.
function tick(v) {
  if (v === 0) return '0';
  return Math.abs(v) < 1e-3 || Math.abs(v) >= 1e6 ? v.toExponential(1) : String(+v.toPrecision(4));
}
function plot(parent, title, names) {
  const present = names.filter((n) => run.columns[n] !== undefined);
  if (present.length === 0) return;
  const box = element('div', { class: 'plot' });
  parent.append(box);
  const width = Math.min(900, Math.max(400, app.clientWidth - 40));
  const chart = new uPlot({
    title, width, height: 260,
    cursor: { sync: { key: sync.key } },
    scales: { x: { time: false } },
    axes: [{}, { size: 70, values: (u, splits) => splits.map(tick) }],
    series: [{ label: 't' }, ...present.map((n, k) => ({
      label: n, stroke: palette[k % palette.length], width: 1.5,
    }))],
    hooks: { draw: [markers] },
  }, [time, ...present.map((n) => run.columns[n])], box);
  const gaps = present.filter((n) => notFinite[n]);
  if (gaps.length) {
    box.append(element('p', { class: 'not-finite' }, `not finite, so not drawn: ${
      gaps.map((n) => `${n} at ${notFinite[n]} rows`).join(', ')}`));
  }
  // a click on a plot takes the animation to that instant
  chart.over.addEventListener('click', () => {
    if (chart.cursor.left == null || chart.cursor.left < 0) return;
    seek(chart.posToVal(chart.cursor.left, 'x'));
  });
  charts.push(chart);
}
{
  const s = sections.run;
  s.append(element('pre', {}, run.summary));
  if (run.rows_shown < run.rows) {
    s.append(element('p', { class: 'thinned' }, `This page shows ${run.rows_shown} of the run's ${
      run.rows} rows: of each stretch of the run its first row and the rows where each column is `
      + 'least and greatest (the plots keep every peak), and the rows around each event. '
      + '`unidyn simulate` writes them all.'));
  }
  if (run.events.length) {
    const list = element('ul', { class: 'events' });
    for (const e of run.events) list.append(element('li', {}, `t = ${e.t}: ${e.what}`));
    s.append(list);
  }
  for (const group of run.groups) plot(s, group.title, group.columns);
}

// --- Phase portraits: each coordinate against its rate, the animation's point on it ------------
const portraits = [];
{
  const s = sections.phase;
  const row = element('div', { class: 'portraits' });
  s.append(row);
  for (const q of data.model.coordinates) {
    const x = run.columns[q], y = run.columns[`der(${q})`];
    if (!x || !y) continue;
    const canvas = element('canvas', { width: 260, height: 220, class: 'portrait' });
    row.append(element('figure', {}, canvas, element('figcaption', {}, `${q} vs der(${q})`)));
    portraits.push({ canvas, x, y });
  }
}
// One more portrait of any two columns, chosen.
{
  const names = Object.keys(run.columns).filter((n) => n !== 't');
  const pick = (initial) => {
    const select = element('select', {});
    for (const n of names) {
      const o = element('option', { value: n }, n);
      if (n === initial) o.selected = true;
      select.append(o);
    }
    return select;
  };
  const q = data.model.coordinates;
  const across = pick(q[0]), up = pick(q.length > 1 ? q[1] : `der(${q[0]})`);
  const canvas = element('canvas', { width: 260, height: 220, class: 'portrait' });
  const chosen = { canvas, x: run.columns[across.value], y: run.columns[up.value] };
  const change = () => {
    chosen.x = run.columns[across.value];
    chosen.y = run.columns[up.value];
    chosen.ranges = null;
    drawPortrait(chosen, index);
  };
  across.addEventListener('change', change);
  up.addEventListener('change', change);
  sections.phase.querySelector('div.portraits').append(
    element('figure', {}, canvas, element('figcaption', {}, across, ' vs ', up)));
  portraits.push(chosen);
}

function drawPortrait(portrait, index) {
  const { canvas, x, y } = portrait;
  const ctx = canvas.getContext('2d');
  const w = canvas.width, h = canvas.height, pad = 12;
  // the finite values' range (a loop: spreading 10^5 values into Math.min overflows the stack)
  const range = (v) => {
    let lo = Infinity, hi = -Infinity;
    for (const x of v) {
      if (x === null) continue;
      lo = Math.min(lo, x);
      hi = Math.max(hi, x);
    }
    if (!(hi >= lo)) { lo = 0; hi = 0; }
    if (hi - lo < 1e-12) { lo -= 1; hi += 1; }
    return [lo, hi];
  };
  // the ranges once per pair of columns, not at every frame
  if (!portrait.ranges) portrait.ranges = [range(x), range(y)];
  const [[x0, x1], [y0, y1]] = portrait.ranges;
  const px = (v) => pad + (v - x0) / (x1 - x0) * (w - 2 * pad);
  const py = (v) => h - pad - (v - y0) / (y1 - y0) * (h - 2 * pad);
  ctx.fillStyle = '#fff';
  ctx.fillRect(0, 0, w, h);
  ctx.strokeStyle = palette[0];
  ctx.beginPath();
  // a value that is not finite breaks the line there
  let drawing = false;
  for (let k = 0; k < x.length; ++k) {
    if (x[k] === null || y[k] === null) {
      drawing = false;
      continue;
    }
    (drawing ? ctx.lineTo : ctx.moveTo).call(ctx, px(x[k]), py(y[k]));
    drawing = true;
  }
  ctx.stroke();
  if (x[index] === null || y[index] === null) return;
  ctx.fillStyle = '#000';
  ctx.beginPath();
  ctx.arc(px(x[index]), py(y[index]), 4, 0, 2 * Math.PI);
  ctx.fill();
}

// --- The run in 3-D: particles as spheres, bodies as their ellipsoids of inertia ---------------
const scene3d = sections.motion;
const controls = element('div', { class: 'controls' });
const play = element('button', {}, 'Pause');
const slider = element('input', { type: 'range', min: 0, max: time.length - 1, value: 0 });
const speed = element('select', {});
for (const v of ['0.25', '0.5', '1', '2', '4']) {
  const o = element('option', { value: v }, `${v}×`);
  if (v === '1') o.selected = true;
  speed.append(o);
}
const frames = element('input', { type: 'checkbox' });
const forcesShown = element('input', { type: 'checkbox' });
forcesShown.checked = true;
const clock = element('span', { class: 'clock' }, 't = 0');
const surfacesShown = element('input', { type: 'checkbox' });
surfacesShown.checked = true;
controls.append(play, slider, speed, element('label', {}, frames, ' body frames'),
  element('label', {}, forcesShown, ' constraint forces'), clock);
if (data.scene.surfaces.length > 0) {
  controls.insertBefore(element('label', {}, surfacesShown, ' surfaces'), clock);
}
scene3d.append(controls);
const view = element('div', { class: 'view' });
scene3d.append(view);

const scene = new Scene();
scene.background = new Color('#f4f4f0');
const camera = new PerspectiveCamera(45, 16 / 9, 0.001, 1000);
const renderer = new WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
renderer.setSize(Math.min(900, app.clientWidth - 40), 480);
view.append(renderer.domElement);
const orbit = new OrbitControls(camera, renderer.domElement);
scene.add(new AmbientLight(0xffffff, 0.6));
const sun = new DirectionalLight(0xffffff, 1.4);
sun.position.set(3, 2, 5);
scene.add(sun);

// The book's frame: E3 up, as three's y is; (x, y, z) → (x, z, −y).
const toView = (x, y, z) => new Vector3(x, z, -y);
const { extent, center } = data.scene;
const size = Math.max(extent, 1e-3);
const grid = new GridHelper(4 * size, 20, 0x999999, 0xcccccc);
// the floor: z = 0, or below the lowest point of the motion (a hanging pendulum)
grid.position.copy(toView(center[0], center[1], Math.min(0, data.scene.lowest)));
scene.add(grid);
const axes = new AxesHelper(0.5 * size);
scene.add(axes);

// The constraints' planes (a square half the grid's width about the motion) and spheres, translucent.
const surfaces = data.scene.surfaces.map((s) => {
  const material = new MeshStandardMaterial({
    color: '#6a8caf', transparent: true, opacity: 0.2, side: DoubleSide, depthWrite: false,
  });
  if (s.kind === 'sphere') {
    const mesh = new Mesh(new SphereGeometry(s.radius, 48, 32), material);
    mesh.position.copy(toView(...s.center));
    return mesh;
  }
  const mesh = new Mesh(new PlaneGeometry(2 * size, 2 * size), material);
  const n = toView(...s.normal);
  // the point of the plane nearest the motion's centre
  const c = toView(...center);
  mesh.position.copy(c.addScaledVector(n, s.offset - n.dot(c)));
  mesh.quaternion.setFromUnitVectors(new Vector3(0, 0, 1), n);
  return mesh;
});
for (const mesh of surfaces) scene.add(mesh);

// A body's shape in its own basis, centred on its centre of mass, its axis of symmetry along e3
// (three's shapes of revolution are along their y: turned onto z); the dimensions as the model
// language's inertia shapes take them.
function shapeGeometry({ shape, dimensions: d }) {
  const alongE3 = (g) => g.rotateX(Math.PI / 2);
  switch (shape) {
    case 'sphere': case 'hollow_sphere': return new SphereGeometry(d[0], 32, 20);
    case 'cylinder': case 'hollow_cylinder': return alongE3(new CylinderGeometry(d[0], d[0], d[1], 40));
    case 'disk': return alongE3(new CylinderGeometry(d[0], d[0], 0.06 * d[0], 48));
    case 'rod': return alongE3(new CylinderGeometry(d[0] / 40, d[0] / 40, d[0], 12));
    case 'box': return new BoxGeometry(d[0], d[1], d[2]);
    case 'ellipsoid': return new SphereGeometry(1, 32, 20).scale(d[0], d[1], d[2]);
    // the centre of mass a quarter of the height above the base
    case 'cone': return alongE3(new ConeGeometry(d[0], d[1], 40).translate(0, d[1] / 4, 0));
    default: return null;
  }
}

// A line along the whole path of a point (x, y, z columns), shown up to the instant.
function trailLine(columns, color) {
  const points = [];
  for (let j = 0; j < time.length; ++j) {
    const p = toView(columns[0][j], columns[1][j], columns[2][j]);
    points.push(p.x, p.y, p.z);
  }
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new Float32BufferAttribute(points, 3));
  return new Line(geometry, new LineBasicMaterial({ color }));
}

const actors = [];
data.scene.particles.forEach((p, k) => {
  const mesh = new Mesh(new SphereGeometry(p.radius, 24, 16),
    new MeshStandardMaterial({ color: palette[k % palette.length] }));
  scene.add(mesh);
  const columns = ['x', 'y', 'z'].map((c) => run.columns[`${p.name}.${c}`]);
  const trail = trailLine(columns, palette[k % palette.length]);
  scene.add(trail);
  actors.push({ kind: 'particle', mesh, trail, columns });
});
data.scene.bodies.forEach((b, k) => {
  const group = new Group();
  const color = b.visual && b.visual.color ? b.visual.color : palette[(k + 3) % palette.length];
  const geometry = b.visual && b.visual.shape ? shapeGeometry(b.visual) : null;
  const shape = new Mesh(geometry || new SphereGeometry(1, 32, 20),
    new MeshStandardMaterial({ color, roughness: 0.6 }));
  if (!geometry) {
    // the ellipsoid of inertia along the principal axes in the body frame
    shape.scale.set(...b.semi_axes);
    const m = new Matrix4();
    const a = b.principal_axes;
    m.set(a[0][0], a[0][1], a[0][2], 0, a[1][0], a[1][1], a[1][2], 0, a[2][0], a[2][1], a[2][2], 0,
      0, 0, 0, 1);
    shape.quaternion.setFromRotationMatrix(m);
  }
  group.add(shape);
  const frame = new AxesHelper(1.5 * Math.max(...b.semi_axes));
  frame.visible = false;
  group.add(frame);
  scene.add(group);
  const columns = ['x', 'y', 'z', 'e0', 'e1', 'e2', 'e3'].map((c) => run.columns[`${b.name}.${c}`]);
  const trail = trailLine(columns, palette[(k + 3) % palette.length]);
  scene.add(trail);
  actors.push({ kind: 'body', group, frame, trail, columns });
});
// The constraint forces as arrows from the particle or body's centre, the largest a quarter of the
// motion's extent long.
const arrows = data.scene.forces.map((owner) => {
  const columns = ['x', 'y', 'z'].map((c) => run.columns[`${owner}.${c}`]);
  const force = ['x', 'y', 'z'].map((c) => run.columns[`${owner}.Fc.${c}`]);
  const arrow = new ArrowHelper(new Vector3(1, 0, 0), new Vector3(), 1, 0xaa0000);
  scene.add(arrow);
  return { arrow, columns, force };
});
let largestForce = 0;
for (const a of arrows) {
  for (let k = 0; k < time.length; ++k) {
    largestForce = Math.max(largestForce, Math.hypot(a.force[0][k], a.force[1][k], a.force[2][k]));
  }
}
// the book's frame in three's: a rotation taking (x, y, z) to (x, z, −y)
const bookToView = new Quaternion().setFromAxisAngle(new Vector3(1, 0, 0), -Math.PI / 2);
// A body that travels far from its size (a rolling disk) is followed by the camera, close enough
// to see it; otherwise the camera takes in the whole motion.
const bodySize = Math.max(0, ...data.scene.bodies.map((b) => Math.max(...b.semi_axes)));
const follow = element('input', { type: 'checkbox' });
follow.checked = bodySize > 0 && size > 4 * bodySize;
controls.insertBefore(element('label', {}, follow, ' follow'), clock);
// from the side and above, 8 body sizes away or 3.9 times the motion's extent
const distance = (follow.checked ? 8 * bodySize : 3.9 * size) / Math.hypot(2.2, 2.8, 1.6);
camera.position.copy(toView(center[0] + 2.2 * distance, center[1] - 2.8 * distance,
  center[2] + 1.6 * distance));
orbit.target.copy(toView(...center));
orbit.update();
// The camera kept at its offset from the first body.
function followBody() {
  const body = actors.find((a) => a.kind === 'body');
  if (!follow.checked || !body) return;
  const offset = camera.position.clone().sub(orbit.target);
  orbit.target.copy(body.group.position);
  camera.position.copy(orbit.target).add(offset);
  orbit.update();
}

let index = 0;
function show(k) {
  index = k;
  cursorTime = time[k];
  for (const actor of actors) {
    const v = actor.columns.map((c) => c[k]);
    // the path so far
    actor.trail.geometry.setDrawRange(0, k + 1);
    if (actor.kind === 'particle') {
      actor.mesh.position.copy(toView(v[0], v[1], v[2]));
    } else {
      actor.group.position.copy(toView(v[0], v[1], v[2]));
      // Q of the body in the book's frame, then the book's frame in three's
      const q = new Quaternion(v[4], v[5], v[6], v[3]);
      actor.group.quaternion.copy(bookToView).multiply(q);
      actor.frame.visible = frames.checked;
    }
  }
  for (const a of arrows) {
    const f = toView(a.force[0][k], a.force[1][k], a.force[2][k]);
    const length = largestForce > 0 ? f.length() / largestForce * 0.25 * size : 0;
    a.arrow.visible = forcesShown.checked && length > 1e-6 * size;
    if (!a.arrow.visible) continue;
    a.arrow.position.copy(toView(a.columns[0][k], a.columns[1][k], a.columns[2][k]));
    a.arrow.setDirection(f.normalize());
    a.arrow.setLength(length, 0.2 * length, 0.1 * length);
  }
  for (const mesh of surfaces) mesh.visible = surfacesShown.checked;
  followBody();
  slider.value = String(k);
  clock.textContent = `t = ${time[k].toFixed(3)}`;
  for (const c of charts) c.redraw(false, false);
  portraits.forEach((p) => drawPortrait(p, k));
  renderer.render(scene, camera);
}

// The animation at the row nearest time t, paused there.
function seek(t) {
  let k = 0;
  while (k + 1 < time.length && Math.abs(time[k + 1] - t) <= Math.abs(time[k] - t)) ++k;
  playing = false;
  play.textContent = 'Play';
  show(k);
}

// Playing: the run's time follows the clock at the speed chosen.
let playing = true, start = performance.now(), startTime = time[0];
const hash = new URLSearchParams(location.hash.slice(1));
if (hash.has('t')) {
  playing = false;
  play.textContent = 'Play';
  const t = Number(hash.get('t'));
  let k = 0;
  while (k + 1 < time.length && time[k + 1] <= t) ++k;
  index = k;
}
play.addEventListener('click', () => {
  playing = !playing;
  play.textContent = playing ? 'Pause' : 'Play';
  start = performance.now();
  startTime = time[index];
});
slider.addEventListener('input', () => {
  show(Number(slider.value));
  start = performance.now();
  startTime = time[index];
});
speed.addEventListener('change', () => {
  start = performance.now();
  startTime = time[index];
});
frames.addEventListener('change', () => show(index));
forcesShown.addEventListener('change', () => show(index));
surfacesShown.addEventListener('change', () => show(index));
orbit.addEventListener('change', () => renderer.render(scene, camera));
function frame() {
  if (playing) {
    let t = startTime + (performance.now() - start) / 1000 * Number(speed.value);
    if (t > time[time.length - 1]) {
      t = time[0];
      start = performance.now();
      startTime = t;
    }
    let k = index;
    if (time[k] > t) k = 0;
    while (k + 1 < time.length && time[k + 1] <= t) ++k;
    if (k !== index || k === 0) show(k);
  }
  requestAnimationFrame(frame);
}
show(index);
// how long the page took to show the motion's first picture (the browser tests print it)
const readyMilliseconds = performance.now();
requestAnimationFrame(frame);
requestAnimationFrame(() => setTimeout(renderMath, 0));

// --- #selftest: what the browser tests check ----------------------------------------------------
// Whether a canvas has pixels of more than one colour.
function drawn(canvas) {
  const probe = document.createElement('canvas');
  probe.width = canvas.width;
  probe.height = canvas.height;
  const ctx = probe.getContext('2d');
  ctx.drawImage(canvas, 0, 0);
  const pixels = ctx.getImageData(0, 0, probe.width, probe.height).data;
  for (let k = 4; k < pixels.length; k += 4) {
    if (pixels[k] !== pixels[0] || pixels[k + 1] !== pixels[1] || pixels[k + 2] !== pixels[2]) {
      return true;
    }
  }
  return false;
}
function selftest() {
  renderMath();
  // the 3-D canvas at two times: drawn, and different
  show(0);
  const first = renderer.domElement.toDataURL();
  show(time.length - 1);
  const last = renderer.domElement.toDataURL();
  show(index);
  // each body's e3 as the view shows it, against Q E3 of its Euler parameters (6.36)
  let orientationError = 0;
  for (const actor of actors.filter((a) => a.kind === 'body')) {
    const [e0, e1, e2, e3] = actor.columns.slice(3).map((c) => c[index]);
    const book = [2 * (e1 * e3 + e0 * e2), 2 * (e2 * e3 - e0 * e1), e0 * e0 - e1 * e1 - e2 * e2 + e3 * e3];
    const seen = new Vector3(0, 0, 1).applyQuaternion(actor.group.quaternion);
    const back = [seen.x, -seen.z, seen.y];  // three's (x, y, z) is the book's (x, z, −y)
    for (let i = 0; i < 3; ++i) orientationError = Math.max(orientationError, Math.abs(back[i] - book[i]));
  }
  const result = {
    errors,
    orientation_error: orientationError,
    plots: charts.length,
    plots_drawn: charts.filter((c) => drawn(c.ctx.canvas)).length,
    portraits: portraits.length,
    portraits_drawn: portraits.filter((p) => drawn(p.canvas)).length,
    scene_drawn: drawn(renderer.domElement),
    scene_moves: first !== last,
    math: document.querySelectorAll('math').length,
    math_errors: document.querySelectorAll('.katex-error').length,
    actors: actors.length,
    arrows: arrows.length,
    surfaces: surfaces.length,
    equilibria: data.equilibria.items ? data.equilibria.items.length : -1,
    modes: data.operating_point.modes ? data.operating_point.modes.length
      : data.operating_point.multipliers ? data.operating_point.multipliers.length : -1,
    ready_ms: Math.round(readyMilliseconds),
  };
  document.body.append(element('pre', { id: 'selftest' }, JSON.stringify(result)));
}
// after the plots' first drawing (uPlot draws on the next frame)
if (hash.has('selftest')) requestAnimationFrame(() => setTimeout(selftest, 100));
