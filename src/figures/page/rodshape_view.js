/* rodshape_view.js: the code of plan.html and validation.html (src/figures/plan_page.cpp inlines
 * it after three.js and OrbitControls, and the data as JSON in <script id="rodshape-data">).
 * Nothing is solved here: the rod's shape at time t is interpolated node by node between the two
 * keyframes (the initial rod, the steps) around t, the arm's joint frames between two samples.
 * World frame: z up, metres. Test hooks: window.rodshape.setTime(t), .state(), .helpers
 * (tests/figures/test_pages.py). */
(function () {
  'use strict';

  var data = JSON.parse(document.getElementById('rodshape-data').textContent);

  // ---- pure helpers (no DOM, no three.js) ------------------------------------------------------

  /** Keyframes of the rod's shape: the initial rod at t = 0, then each step at its time. */
  function keyframes(d) {
    var keys = [{ t: 0, shape: d.initial, step: 0 }];
    d.steps.forEach(function (s) {
      keys.push({ t: s.t, shape: s.shape, step: s.index });
    });
    return keys;
  }

  /** The index i with keys[i].t <= t < keys[i + 1].t (clamped to the ends). */
  function segmentAt(times, t) {
    if (times.length < 2 || t <= times[0]) return 0;
    if (t >= times[times.length - 1]) return times.length - 2;
    var lo = 0, hi = times.length - 1;
    while (hi - lo > 1) {
      var mid = (lo + hi) >> 1;
      if (times[mid] <= t) lo = mid; else hi = mid;
    }
    return lo;
  }

  function mix(a, b, f) {
    return [a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1]), a[2] + f * (b[2] - a[2])];
  }

  /** Node-by-node interpolation of two polylines (resampled by index when their sizes differ). */
  function mixShapes(a, b, f) {
    if (f <= 0) return a.slice();
    if (f >= 1) return b.slice();
    var n = Math.max(a.length, b.length), out = [];
    for (var i = 0; i < n; ++i) {
      var ia = Math.round(i * (a.length - 1) / Math.max(n - 1, 1));
      var ib = Math.round(i * (b.length - 1) / Math.max(n - 1, 1));
      out.push(mix(a[ia], b[ib], f));
    }
    return out;
  }

  /** The rod at time t: {shape, step (the last keyframe reached), f (the way to the next)}. */
  function shapeAt(keys, t) {
    if (keys.length === 1) return { shape: keys[0].shape, step: keys[0].step, f: 0 };
    var times = keys.map(function (k) { return k.t; });
    var i = segmentAt(times, t);
    var span = keys[i + 1].t - keys[i].t;
    var f = span > 0 ? Math.min(Math.max((t - keys[i].t) / span, 0), 1) : (t >= keys[i + 1].t ? 1 : 0);
    var reached = f >= 1 ? keys[i + 1].step : keys[i].step;
    return { shape: mixShapes(keys[i].shape, keys[i + 1].shape, f), step: reached, f: f };
  }

  /** The arm's joint frames at time t (linear between samples), or null without an arm. */
  function armAt(arm, t) {
    if (!arm || arm.frames.length === 0) return null;
    if (arm.frames.length === 1) return arm.frames[0];
    var i = segmentAt(arm.t, t);
    var span = arm.t[i + 1] - arm.t[i];
    var f = span > 0 ? Math.min(Math.max((t - arm.t[i]) / span, 0), 1) : 1;
    var a = arm.frames[i], b = arm.frames[i + 1];
    return a.map(function (p, k) { return mix(p, b[k], f); });
  }

  /** The SVG's colour ramp (src/figures/svg_drawing.cpp): dark blue, purple, pink, orange. */
  function stepColour(k, n) {
    var ramp = [[13, 8, 135], [126, 3, 168], [204, 71, 120], [240, 130, 50]];
    var t = n > 1 ? k / (n - 1) : 1, x = t * (ramp.length - 1);
    var i = Math.min(Math.floor(x), ramp.length - 2), f = x - i;
    var c = [0, 1, 2].map(function (j) { return Math.round((1 - f) * ramp[i][j] + f * ramp[i + 1][j]); });
    return (c[0] << 16) | (c[1] << 8) | c[2];
  }

  function hex(colour) { return '#' + ('000000' + colour.toString(16)).slice(-6); }

  function distance(a, b) {
    return Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
  }

  /** The box around everything drawn: {lo, hi, centre, span}. */
  function bounds(d) {
    var lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
    function add(p, r) {
      r = r || 0;
      for (var j = 0; j < 3; ++j) {
        lo[j] = Math.min(lo[j], p[j] - r);
        hi[j] = Math.max(hi[j], p[j] + r);
      }
    }
    d.initial.forEach(function (p) { add(p); });
    d.target.forEach(function (p) { add(p); });
    d.steps.forEach(function (s) { s.shape.forEach(function (p) { add(p); }); });
    add(d.clamp);
    if (d.arm) d.arm.frames.forEach(function (f) { f.forEach(function (p) { add(p); }); });
    if (d.base_arm) d.base_arm.frames.forEach(function (f) { f.forEach(function (p) { add(p); }); });
    if (d.base_path) d.base_path.p.forEach(function (p) { add(p); });
    d.obstacles.forEach(function (o) {
      if (o.shape === 'sphere') add(o.center, o.radius);
      if (o.shape === 'capsule') { add(o.from, o.radius); add(o.to, o.radius); }
      if (o.shape === 'box') add(o.center, 0.5 * Math.max(o.size[0], o.size[1], o.size[2]));
    });
    if (!isFinite(lo[0])) { lo = [-0.5, -0.5, -0.5]; hi = [0.5, 0.5, 0.5]; }
    var span = Math.max(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2], 1e-3);
    return { lo: lo, hi: hi, span: span, centre: mix(lo, hi, 0.5) };
  }

  var keys = keyframes(data);
  var duration = Math.max(data.duration || 0, keys[keys.length - 1].t);
  var box = bounds(data);
  var helpers = {
    keyframes: keyframes, segmentAt: segmentAt, mixShapes: mixShapes, shapeAt: shapeAt,
    armAt: armAt, stepColour: stepColour, bounds: bounds, distance: distance
  };

  // ---- the page's frame: header, side panel, controls -------------------------------------------

  function element(tag, attributes, parent, text) {
    var e = document.createElement(tag);
    Object.keys(attributes || {}).forEach(function (k) { e.setAttribute(k, attributes[k]); });
    if (text !== undefined) e.textContent = text;
    if (parent) parent.appendChild(e);
    return e;
  }

  var head = element('div', { id: 'rs-head' }, document.body);
  element('h1', {}, head, (data.kind === 'validation' ? 'rodshape validation: ' : 'rodshape plan: ') + data.source);
  element('div', { 'class': 'summary' }, head, data.summary);
  if (data.validation) element('div', { 'class': 'summary' }, head, 'validation: ' + data.validation.summary);
  if (data.status !== 'complete' && data.message) element('div', { 'class': 'message' }, head, data.message);
  var view = element('div', { id: 'rs-view' }, document.body);
  var side = element('div', { id: 'rs-side' }, document.body);
  var controls = element('div', { id: 'rs-controls' }, document.body);
  var playButton = element('button', { id: 'rs-play', type: 'button' }, controls, 'play');
  var slider = element('input', { id: 'rs-slider', type: 'range', min: '0', max: '1000', step: '1', value: '0' }, controls);
  var timeLabel = element('span', { id: 'rs-time' }, controls, '');

  function layout() {
    var top = head.offsetHeight;
    view.style.top = top + 'px';
    side.style.top = top + 'px';
  }
  layout();

  // ---- the 3D scene -------------------------------------------------------------------------------

  var THREE = window.THREE;
  var renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(window.devicePixelRatio || 1);
  renderer.setClearColor(0xf4f5f7);
  view.appendChild(renderer.domElement);
  var scene = new THREE.Scene();
  var camera = new THREE.PerspectiveCamera(35, 1, box.span * 1e-3, box.span * 100);
  camera.up.set(0, 0, 1);
  // Looking at the rod (with an arm, the scene is the arm's size and the rod a small part of it).
  var rodBox = bounds({ initial: data.initial, target: data.target, steps: data.steps, clamp: data.clamp, arm: null, obstacles: [] });
  var centre = new THREE.Vector3(rodBox.centre[0], rodBox.centre[1], rodBox.centre[2]);
  var reach = (data.arm || data.base_arm) ? 0.65 * box.span + 0.4 * rodBox.span : box.span;
  camera.position.set(centre.x + 0.8 * reach, centre.y - 1.9 * reach, centre.z + 0.7 * reach);
  var orbit = new THREE.OrbitControls(camera, renderer.domElement);
  orbit.target.copy(centre);
  orbit.update();
  scene.add(new THREE.AmbientLight(0xffffff, 0.55));
  var sun = new THREE.DirectionalLight(0xffffff, 0.75);
  sun.position.set(0.4, -0.8, 1.0);
  scene.add(sun);

  function v3(p) { return new THREE.Vector3(p[0], p[1], p[2]); }

  // Ground grid (at the lowest point drawn) and axes (at the origin, a fifth of the scene long).
  var gridStep = Math.pow(10, Math.floor(Math.log10(box.span / 2)));
  var gridSize = Math.ceil(2 * box.span / gridStep) * gridStep;
  var grid = new THREE.GridHelper(gridSize, Math.round(gridSize / gridStep) * 2, 0xb0b4ba, 0xdadde1);
  grid.rotation.x = Math.PI / 2;
  grid.position.set(Math.round(box.centre[0] / gridStep) * gridStep, Math.round(box.centre[1] / gridStep) * gridStep, box.lo[2]);
  scene.add(grid);
  scene.add(new THREE.AxesHelper(0.2 * box.span));

  // The rod's section (its circumscribed radius), or 1% of its length when the task gives none;
  // at least 0.2% of the scene, so that a thin rod stays visible.
  var drawRadius = Math.max(data.radius > 0 ? data.radius : 0.01 * data.length, 0.002 * box.span);
  var markRadius = 0.006 * box.span;
  var nSteps = data.steps.length;

  function line(points, colour, opacity) {
    var g = new THREE.BufferGeometry().setFromPoints(points.map(v3));
    var m = new THREE.LineBasicMaterial({ color: colour, transparent: opacity < 1, opacity: opacity });
    var l = new THREE.Line(g, m);
    scene.add(l);
    return l;
  }

  function tubeGeometry(points, radius) {
    var curve = new THREE.CatmullRomCurve3(points.map(v3));
    return new THREE.TubeGeometry(curve, Math.max(24, 2 * points.length), radius, 12, false);
  }

  function tube(points, radius, colour, opacity) {
    if (points.length < 2) return null;
    var m = new THREE.MeshLambertMaterial({ color: colour, transparent: opacity < 1, opacity: opacity });
    var mesh = new THREE.Mesh(tubeGeometry(points, radius), m);
    scene.add(mesh);
    return mesh;
  }

  function ball(p, radius, colour, opacity) {
    var m = new THREE.MeshLambertMaterial({ color: colour, transparent: opacity < 1, opacity: opacity === undefined ? 1 : opacity });
    var mesh = new THREE.Mesh(new THREE.SphereBufferGeometry(radius, 20, 14), m);
    mesh.position.copy(v3(p));
    scene.add(mesh);
    return mesh;
  }

  /** Points of `size` px; `onTop`: seen through the rod (the target points lie inside it). */
  function dots(points, colour, size, onTop) {
    if (points.length === 0) return null;
    var g = new THREE.BufferGeometry().setFromPoints(points.map(v3));
    // On top: in the see-through pass (after the see-through tubes), last, without a depth test.
    var m = new THREE.PointsMaterial({ color: colour, size: size, sizeAttenuation: false, depthTest: !onTop, transparent: Boolean(onTop) });
    var p = new THREE.Points(g, m);
    if (onTop) p.renderOrder = 10;
    scene.add(p);
    return p;
  }

  /** A cylinder from a to b (the arm's links, capsules). */
  function placeCylinder(mesh, a, b) {
    var from = v3(a), to = v3(b), axis = to.clone().sub(from);
    var length = Math.max(axis.length(), 1e-9);
    mesh.position.copy(from.clone().add(to).multiplyScalar(0.5));
    mesh.scale.set(1, length, 1);
    mesh.quaternion.setFromUnitVectors(new THREE.Vector3(0, 1, 0), axis.normalize());
  }

  function cylinder(radius, colour, opacity) {
    var m = new THREE.MeshLambertMaterial({ color: colour, transparent: opacity < 1, opacity: opacity });
    var mesh = new THREE.Mesh(new THREE.CylinderBufferGeometry(radius, radius, 1, 16), m);
    scene.add(mesh);
    return mesh;
  }

  // The scene's obstacles, grey and see-through.
  var obstacleColour = 0x8a8f98, obstacleOpacity = 0.4;
  data.obstacles.forEach(function (o) {
    if (o.shape === 'sphere') ball(o.center, o.radius, obstacleColour, obstacleOpacity);
    if (o.shape === 'capsule') {
      placeCylinder(cylinder(o.radius, obstacleColour, obstacleOpacity), o.from, o.to);
      ball(o.from, o.radius, obstacleColour, obstacleOpacity);
      ball(o.to, o.radius, obstacleColour, obstacleOpacity);
    }
    if (o.shape === 'box') {
      var m = new THREE.MeshLambertMaterial({ color: obstacleColour, transparent: true, opacity: obstacleOpacity });
      var mesh = new THREE.Mesh(new THREE.BoxBufferGeometry(o.size[0], o.size[1], o.size[2]), m);
      var q = o.rotation, basis = new THREE.Matrix4();  // q = [w, x, y, z], as in plan.json
      basis.compose(v3(o.center), new THREE.Quaternion(q[1], q[2], q[3], q[0]), new THREE.Vector3(1, 1, 1));
      mesh.applyMatrix(basis);
      scene.add(mesh);
    }
    if (o.shape === 'half_space') {
      // The plane n·p = offset as a square around the scene, on the solid side's face.
      var n = v3(o.normal).normalize(), c = centre.clone();
      var along = (o.offset / Math.hypot(o.normal[0], o.normal[1], o.normal[2])) - n.dot(c);
      var plane = new THREE.Mesh(new THREE.PlaneBufferGeometry(2 * box.span, 2 * box.span),
        new THREE.MeshLambertMaterial({ color: obstacleColour, transparent: true, opacity: 0.3, side: THREE.DoubleSide }));
      plane.position.copy(c.add(n.clone().multiplyScalar(along)));
      plane.quaternion.setFromUnitVectors(new THREE.Vector3(0, 0, 1), n);
      scene.add(plane);
    }
  });
  if (data.workspace_box) {
    scene.add(new THREE.Box3Helper(new THREE.Box3(v3(data.workspace_box.lower), v3(data.workspace_box.upper)), 0x2a9d4a));
  }

  // Static: the initial and final shapes (see-through tubes), each step's shape (lines of the
  // ramp), the objective points (dots), the target points (red balls, joined), the path.
  var finalColour = stepColour(Math.max(nSteps - 1, 0), nSteps);
  tube(data.initial, drawRadius, 0x9a9a9a, 0.35);
  data.steps.forEach(function (s, k) {
    line(s.shape, stepColour(k, nSteps), 0.8);
    dots(s.objective, stepColour(k, nSteps), 4);
  });
  if (nSteps > 0) tube(data.steps[nSteps - 1].shape, drawRadius, finalColour, 0.35);
  dots(data.target, 0xd62728, 7, true);
  if (data.target_curve.length > 1) line(data.target_curve, 0xd62728, 0.6);
  ball(data.clamp, Math.max(markRadius, 1.2 * drawRadius), 0x222222);
  if (data.path.p.length > 1) line(data.path.p, 0x555555, 0.6);
  if (data.base_path && data.base_path.p.length > 1) line(data.base_path.p, 0x1b6f8a, 0.6);

  // Moving: the rod (an orange tube), the end effector (a ball), the arm.
  var rod = tube(data.initial, drawRadius * 1.05, 0xe4572e, 1);
  var effector = ball(data.initial[data.initial.length - 1], Math.max(markRadius, 1.2 * drawRadius), 0x333333);
  // A moving base: its gripper (a ball at the rod's base end).
  var baseEffector = data.base_path ? ball(data.initial[0], Math.max(markRadius, 1.2 * drawRadius), 0x1b6f8a) : null;
  /** An arm's joints (balls) and links (cylinders), placed by placeArm at each time. */
  function armMeshes(arm) {
    var meshes = { links: [], joints: [] };
    if (!arm || arm.frames.length === 0) return meshes;
    var armRadius = 0.012 * box.span;
    arm.frames[0].forEach(function (p, k) {
      meshes.joints.push(ball(p, armRadius * 1.35, 0x39424e));
      if (k > 0) meshes.links.push(cylinder(armRadius, 0x6c7a89, 1));
    });
    return meshes;
  }
  function placeArm(meshes, frame) {
    if (!frame) return;
    frame.forEach(function (p, k) {
      meshes.joints[k].position.copy(v3(p));
      if (k > 0) placeCylinder(meshes.links[k - 1], frame[k - 1], p);
    });
  }
  var tipArm = armMeshes(data.arm), baseArm = armMeshes(data.base_arm);

  // A validation: the plant's last equilibrium (green) and the markers seen at the last frame.
  var runIndex = 0, plantMesh = null, markerMeshes = [];
  function showRun(r) {
    runIndex = r;
    if (plantMesh) { scene.remove(plantMesh); plantMesh.geometry.dispose(); }
    markerMeshes.forEach(function (m) { scene.remove(m); });
    markerMeshes = [];
    var run = data.validation.runs[r];
    if (!run) return;
    plantMesh = tube(run.plant_final, drawRadius, 0x2ca02c, 0.75);
    if (run.markers.length > 0) markerMeshes.push(dots(run.markers, 0x111111, 7, true));
    if (run.cloud && run.cloud.length > 0) markerMeshes.push(dots(run.cloud, 0x1f77b4, 3, true));
    drawPlot();
    listCheckpoints(run);
  }

  /** A closed-loop run's checkpoints: when, at which waypoint, what the loop did. */
  function listCheckpoints(run) {
    if (!checkpointList) return;
    checkpointList.textContent = '';
    if (run.checkpoints.length === 0) return;
    element('h2', {}, checkpointList, 'Checkpoints (' + run.checkpoints.length + ')');
    run.checkpoints.forEach(function (c) {
      element('div', { 'class': 'checkpoint' }, checkpointList,
        't = ' + c.t.toFixed(2) + ' s, waypoint ' + c.waypoint + ': ' +
        (c.replanned ? 're-planned' : 'kept') + (c.consistent ? '' : ' (estimate not consistent)') +
        (c.message ? ' \u2014 ' + c.message : ''));
    });
  }

  // ---- side panel: legend, run selector, plot ---------------------------------------------------

  function legendRow(colour, text, round) {
    var row = element('div', { 'class': 'row' }, side);
    element('span', { 'class': round ? 'dot' : 'swatch', style: 'background:' + colour }, row);
    element('span', {}, row, text);
  }
  element('h2', {}, side, 'Legend');
  legendRow('#e4572e', 'the rod at the time on the slider');
  legendRow('#9a9a9a', 'initial rod');
  if (nSteps > 0) {
    legendRow('linear-gradient(90deg,' + hex(stepColour(0, nSteps)) + ',' + hex(finalColour) + ')', 'steps 1 \u2026 ' + nSteps + ' and their objective points');
    legendRow(hex(finalColour), 'final rod (step ' + nSteps + ')');
  }
  legendRow('#d62728', 'target points', true);
  if (data.target_curve.length > 1) legendRow('#e88a8b', "the target's B-spline");
  legendRow('#222222', data.base_path ? 'the base end where it starts' : 'clamp', true);
  legendRow('#555555', 'end-effector path');
  if (data.base_path) legendRow('#1b6f8a', "the base gripper's path (a moving base)");
  if (data.arm) legendRow('#6c7a89', 'arm (' + data.arm.name + '): links between joint frames');
  if (data.base_arm) legendRow('#6c7a89', 'base arm (' + data.base_arm.name + '): holds the base end');
  if (data.obstacles.length) legendRow('#8a8f98', 'obstacles (' + data.obstacles.length + ')');
  if (data.workspace_box) legendRow('#2a9d4a', 'workspace box');
  if (data.validation) {
    legendRow('#2ca02c', "plant's rod at the end (the real rod)");
    var seesCloud = data.validation.runs.some(function (run) { return run.cloud && run.cloud.length > 0; });
    if (seesCloud) legendRow('#1f77b4', "the depth camera's cloud at the last frame", true);
    else legendRow('#111111', 'markers seen at the last frame', true);
    if (data.validation.runs.length > 1) {
      element('h2', {}, side, 'Run');
      var select = element('select', { id: 'rs-run' }, side);
      data.validation.runs.forEach(function (run, r) {
        element('option', { value: String(r) }, select, 'run ' + (r + 1) + ' (seed ' + run.seed + ')');
      });
      select.addEventListener('change', function () { showRun(Number(select.value)); });
    }
  }
  element('h2', {}, side, data.validation ? 'Errors over time (mm, log)' : 'Elastic energy at the steps (J)');
  var plot = element('canvas', { id: 'rs-plot', width: '250', height: '150' }, side);
  var plotNote = element('div', { 'class': 'note' }, side, '');
  var checkpointList = data.validation ? element('div', { id: 'rs-checkpoints' }, side) : null;
  element('h2', {}, side, 'Mouse');
  element('div', {}, side, 'drag: turn; right-drag: pan; wheel: zoom. Grid lines every ' +
    (gridStep >= 1 ? gridStep + ' m' : Math.round(gridStep * 1000) + ' mm') + '.');

  function plotSeries() {
    if (data.validation) {
      var run = data.validation.runs[runIndex];
      return [  // the true error first: the measured ones start on top of it
        { t: run.t, v: run.true_error, colour: '#2ca02c', name: 'true' },
        { t: run.t, v: run.error_2d, colour: '#ff7f0e', name: '2D' },
        { t: run.t, v: run.error_3d, colour: '#1f77b4', name: '3D' }
      ];
    }
    return [{ t: keys.map(function (k) { return k.t; }),
      v: [data.initial_energy].concat(data.steps.map(function (s) { return s.energy; })),
      colour: '#7e03a8', name: 'energy' }];
  }

  var currentTime = 0;
  function drawPlot() {
    var ctx = plot.getContext('2d'), w = plot.width, h = plot.height, pad = 6;
    ctx.clearRect(0, 0, w, h);
    ctx.fillStyle = '#fff';
    ctx.fillRect(0, 0, w, h);
    var series = plotSeries(), log = Boolean(data.validation);
    var lo = Infinity, hi = -Infinity;
    series.forEach(function (s) {
      s.v.forEach(function (v) {
        if (v === null || !isFinite(v) || (log && v <= 0)) return;
        var y = log ? Math.log10(v * 1e3) : v;
        lo = Math.min(lo, y); hi = Math.max(hi, y);
      });
    });
    if (!isFinite(lo)) { lo = 0; hi = 1; }
    if (!log) lo = Math.min(lo, 0);
    if (hi - lo < 1e-12) hi = lo + 1;
    var T = Math.max(duration, 1e-9);
    function X(t) { return pad + (w - 2 * pad) * t / T; }
    function Y(v) { var y = log ? Math.log10(v * 1e3) : v; return h - pad - (h - 2 * pad) * (y - lo) / (hi - lo); }
    series.forEach(function (s) {
      ctx.strokeStyle = s.colour;
      ctx.lineWidth = 1.3;
      ctx.beginPath();
      var started = false;
      s.v.forEach(function (v, k) {
        if (v === null || !isFinite(v) || (log && v <= 0)) return;
        if (started) ctx.lineTo(X(s.t[k]), Y(v)); else { ctx.moveTo(X(s.t[k]), Y(v)); started = true; }
      });
      ctx.stroke();
    });
    if (data.validation) {
      ctx.fillStyle = '#555';
      data.validation.runs[runIndex].checkpoints.forEach(function (c) {
        ctx.fillRect(X(c.t) - 1, h - pad - 6, 2, 6);
      });
    }
    ctx.strokeStyle = '#e4572e';
    ctx.beginPath();
    ctx.moveTo(X(currentTime), 0);
    ctx.lineTo(X(currentTime), h);
    ctx.stroke();
    plotNote.textContent = log
      ? 'from ' + Math.pow(10, lo).toPrecision(2) + ' to ' + Math.pow(10, hi).toPrecision(2) + ' mm; blue 3D, orange 2D, green true; ticks: checkpoints'
      : 'from ' + lo.toPrecision(3) + ' to ' + hi.toPrecision(3) + ' J over ' + duration.toFixed(2) + ' s';
  }

  // ---- time ---------------------------------------------------------------------------------------

  var current = { shape: data.initial, step: 0, f: 0 }, currentArm = null;
  function setTime(t) {
    currentTime = Math.min(Math.max(Number(t) || 0, 0), duration);
    current = shapeAt(keys, currentTime);
    if (rod && current.shape.length > 1) {
      rod.geometry.dispose();
      rod.geometry = tubeGeometry(current.shape, drawRadius * 1.05);
    }
    effector.position.copy(v3(current.shape[current.shape.length - 1]));
    if (baseEffector) baseEffector.position.copy(v3(current.shape[0]));
    currentArm = armAt(data.arm, currentTime);
    placeArm(tipArm, currentArm);
    placeArm(baseArm, armAt(data.base_arm, currentTime));
    slider.value = String(duration > 0 ? Math.round(1000 * currentTime / duration) : 0);
    timeLabel.textContent = 't = ' + currentTime.toFixed(2) + ' / ' + duration.toFixed(2) + ' s, step ' + current.step + ' of ' + nSteps;
    drawPlot();
    render();
  }

  var playing = false, last = null;
  function tick(now) {
    if (!playing) return;
    if (last !== null) {
      var t = currentTime + (now - last) / 1000;
      if (t >= duration) { t = duration; pause(); }
      setTime(t);
    }
    last = now;
    if (playing) window.requestAnimationFrame(tick);
  }
  function play() {
    if (currentTime >= duration) setTime(0);
    playing = true;
    last = null;
    playButton.textContent = 'pause';
    window.requestAnimationFrame(tick);
  }
  function pause() {
    playing = false;
    playButton.textContent = 'play';
  }
  playButton.addEventListener('click', function () { if (playing) pause(); else play(); });
  slider.addEventListener('input', function () { pause(); setTime(duration * Number(slider.value) / 1000); });

  function render() { renderer.render(scene, camera); }
  function resize() {
    layout();
    var w = Math.max(view.clientWidth, 50), h = Math.max(view.clientHeight, 50);
    renderer.setSize(w, h);
    camera.aspect = w / h;
    camera.updateProjectionMatrix();
    render();
  }
  orbit.addEventListener('change', render);
  window.addEventListener('resize', resize);
  resize();
  if (data.validation) showRun(0);
  setTime(0);

  /** What the page shows now, for tests: time, the rod's nodes, its tip, the arm's frames. */
  function state() {
    return {
      ready: true,
      kind: data.kind,
      t: currentTime,
      duration: duration,
      playing: playing,
      step: current.step,
      steps: nSteps,
      shape: current.shape,
      tip: current.shape[current.shape.length - 1],
      arm: currentArm,
      run: data.validation ? runIndex : null,
      canvas: { width: renderer.domElement.width, height: renderer.domElement.height }
    };
  }

  window.rodshape = {
    data: data, setTime: setTime, state: state, play: play, pause: pause,
    showRun: data.validation ? showRun : null, helpers: helpers
  };
})();
