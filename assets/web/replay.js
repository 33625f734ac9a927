// dashbed's HTML replay: decodes the run inlined in the page (replay-data), builds the scene with
// three.js, and plays, scrubs and explains it. The pure parts (decoding, interpolation, timeline
// layout) are exported for Node's test runner (tests/replay/replay.test.js).
"use strict";

// ---- decoding --------------------------------------------------------------------------------

/** The bytes of a base64 text as an ArrayBuffer. */
function decodeBase64(text) {
  const binary = typeof atob === "function" ? atob(text) : Buffer.from(text, "base64").toString("binary");
  const bytes = new Uint8Array(binary.length);
  for (let i = 0; i < binary.length; ++i) bytes[i] = binary.charCodeAt(i);
  return bytes.buffer;
}

/** A typed array of `Type` over the base64 text's bytes. */
function decodeArray(text, Type) {
  return new Type(decodeBase64(text));
}

/** Quantised poses (int16: positions in units of `unit` metres, quaternions in 1/32767) as floats. */
function decodePoses(text, unit) {
  const raw = decodeArray(text, Int16Array);
  const out = new Float32Array(raw.length);
  for (let i = 0; i < raw.length; ++i) out[i] = (i % 7 < 3) ? raw[i] * unit : raw[i] / 32767;
  return out;
}

// ---- time ------------------------------------------------------------------------------------

/** The sample interval holding time t: [i, i + 1] and the fraction f of the way (clamped to the samples). */
function sampleAt(times, t) {
  const n = times.length;
  if (n === 0) return { i: 0, j: 0, f: 0 };
  if (t <= times[0]) return { i: 0, j: 0, f: 0 };
  if (t >= times[n - 1]) return { i: n - 1, j: n - 1, f: 0 };
  let lo = 0, hi = n - 1;  // times[lo] <= t < times[hi]
  while (hi - lo > 1) {
    const mid = (lo + hi) >> 1;
    if (times[mid] <= t) lo = mid; else hi = mid;
  }
  return { i: lo, j: hi, f: (t - times[lo]) / (times[hi] - times[lo]) };
}

/**
 * The pose at `at` (sampleAt) of the pose starting at `offset` within each sample of `stride`
 * numbers: position lerped, quaternion normalised-lerped along the shorter arc. [x y z qx qy qz qw]
 */
function poseAt(poses, stride, offset, at) {
  const a = at.i * stride + offset, b = at.j * stride + offset, f = at.f;
  const out = new Array(7);
  for (let k = 0; k < 3; ++k) out[k] = poses[a + k] + (poses[b + k] - poses[a + k]) * f;
  let dot = 0;
  for (let k = 3; k < 7; ++k) dot += poses[a + k] * poses[b + k];
  const sign = dot < 0 ? -1 : 1;
  let norm = 0;
  for (let k = 3; k < 7; ++k) {
    out[k] = poses[a + k] * (1 - f) + sign * poses[b + k] * f;
    norm += out[k] * out[k];
  }
  norm = Math.sqrt(norm) || 1;
  for (let k = 3; k < 7; ++k) out[k] /= norm;
  return out;
}

// ---- timeline --------------------------------------------------------------------------------

/**
 * The timeline's lanes: one per robot, each with the actions it takes part in (a handoff in both
 * robots' lanes) as {index, left, width} in fractions of `duration`.
 */
function laneLayout(robots, actions, duration) {
  const span = duration > 0 ? duration : 1;
  return robots.map((robot) => ({
    robot,
    bars: actions.flatMap((action, index) => action.robots.includes(robot) ? [{
      index,
      left: Math.max(0, action.start / span),
      width: Math.max(0.002, (action.end - action.start) / span),
    }] : []),
  }));
}

/**
 * Robot r's values of a signal stored [sample][robot] as a polyline in a w x h box: x by time
 * over [0, duration], y from 0 (bottom) to `top`.
 */
function signalPolyline(times, values, robots, r, duration, top, w, h) {
  const points = [];
  const n = times.length;
  for (let i = 0; i < n; ++i) {
    const x = duration > 0 ? (times[i] / duration) * w : 0;
    const y = h - Math.min(1, values[i * robots + r] / top) * h;
    points.push([x, y]);
  }
  return points;
}

/** Settings from the page's fragment: #t=16&camera=front&action=3&paused. */
function fragmentSettings(hash) {
  const settings = {};
  for (const part of hash.replace(/^#/, "").split("&")) {
    if (!part) continue;
    const [key, value] = part.split("=");
    settings[decodeURIComponent(key)] = value === undefined ? true : decodeURIComponent(value);
  }
  return settings;
}

// ---- the page --------------------------------------------------------------------------------

function element(tag, attributes = {}, text = "") {
  const node = document.createElement(tag);
  for (const [key, value] of Object.entries(attributes)) node.setAttribute(key, value);
  if (text) node.textContent = text;
  return node;
}

function fixed(value, digits = 2) { return Number(value).toFixed(digits); }

function main() {
  const THREE = window.THREE;
  const data = JSON.parse(document.getElementById("replay-data").textContent);
  const report = data.report;
  const times = decodeArray(data.times, Float32Array);
  const linkPoses = decodePoses(data.link_poses, data.position_unit);
  const objectPoses = decodePoses(data.object_poses, data.position_unit);
  const duration = times.length ? times[times.length - 1] : 0;
  const robotNames = data.robots.map((r) => r.name);
  const linkStride = robotNames.length * data.links.length * 7;
  const objectStride = data.objects.length * 7;
  const signals = {};
  for (const [name, text] of Object.entries(data.signals)) signals[name] = decodeArray(text, Float32Array);

  // header
  const header = document.getElementById("header");
  header.append(element("span", { class: "verdict " + (report.passed ? "passed" : "failed") },
                        report.passed ? "PASSED" : "FAILED"));
  header.append(element("span", {}, `${data.world}: ${report.passed_actions} of ${report.actions.length} actions passed`));
  header.append(element("span", { class: report.execution_passed ? "passed" : "failed" },
                        report.execution_passed ? "execution clean" : "execution: " + report.execution_failure));
  header.append(element("span", { class: report.ready ? "passed" : "failed" },
                        report.ready ? "hardware ready" : "hardware not ready"));
  header.append(element("span", {}, `plan ${data.plan}, ${fixed(report.simulated_time, 1)} s simulated`));

  // scene
  const canvas = document.getElementById("scene");
  const renderer = new THREE.WebGLRenderer({ canvas, antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(window.devicePixelRatio || 1);
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0xe9ecef);
  scene.add(new THREE.HemisphereLight(0xffffff, 0x8a8a80, 1.6));
  const sun = new THREE.DirectionalLight(0xffffff, 1.4);
  sun.position.set(2, -3, 5);
  scene.add(sun);
  const camera = new THREE.PerspectiveCamera(45, 1, 0.02, 100);
  camera.up.set(0, 0, 1);

  const color = (c) => new THREE.Color(c[0], c[1], c[2]);
  const place = (object, pose) => {
    object.position.set(pose[0], pose[1], pose[2]);
    object.quaternion.set(pose[3], pose[4], pose[5], pose[6]);
  };
  for (const fixture of data.fixtures) {
    const material = new THREE.MeshStandardMaterial({ color: color(fixture.color), roughness: 0.9 });
    for (const box of fixture.boxes) {
      const mesh = new THREE.Mesh(new THREE.BoxGeometry(...box.size), material);
      place(mesh, box.pose);
      mesh.userData.fixture = fixture.name;
      scene.add(mesh);
    }
  }
  for (const region of data.regions) {
    const edges = new THREE.LineSegments(new THREE.EdgesGeometry(new THREE.BoxGeometry(...region.size)),
                                         new THREE.LineBasicMaterial({ color: 0x3366cc }));
    const frame = new THREE.Group();
    place(frame, region.pose);
    edges.position.z = region.size[2] / 2;  // the pose is the floor's centre
    frame.add(edges);
    scene.add(frame);
  }
  const geometries = data.meshes.map((mesh) => {
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute("position", new THREE.BufferAttribute(decodeArray(mesh.positions, Float32Array), 3));
    geometry.setAttribute("normal", new THREE.BufferAttribute(decodeArray(mesh.normals, Float32Array), 3));
    geometry.setAttribute("color", new THREE.BufferAttribute(decodeArray(mesh.colors, Uint8Array), 3, true));
    geometry.setIndex(new THREE.BufferAttribute(decodeArray(mesh.indices, Uint32Array), 1));
    return geometry;
  });
  const robotMaterial = new THREE.MeshStandardMaterial({ vertexColors: true, roughness: 0.6, metalness: 0.1 });
  const links = robotNames.map(() => data.links.map((link) => {
    const mesh = new THREE.Mesh(geometries[link.mesh], robotMaterial);
    scene.add(mesh);
    return mesh;
  }));
  const objects = data.objects.map((object) => {
    const mesh = new THREE.Mesh(new THREE.BoxGeometry(...object.size),
                                new THREE.MeshStandardMaterial({ color: color(object.color), roughness: 0.5 }));
    mesh.userData.name = object.name;
    scene.add(mesh);
    return mesh;
  });
  const marker = new THREE.Mesh(new THREE.SphereGeometry(0.03, 16, 12),
                                new THREE.MeshBasicMaterial({ color: 0xd03a2f, transparent: true, opacity: 0.8 }));
  marker.visible = false;
  scene.add(marker);
  const floor = new THREE.GridHelper(6, 30, 0xb0b0a8, 0xcfcfc8);
  floor.rotation.x = Math.PI / 2;
  scene.add(floor);

  // camera: orbit about a target (drag), pan (right drag or shift), zoom (wheel); presets
  const view = { target: new THREE.Vector3(), distance: 3, azimuth: 0, elevation: 0.5 };
  const applyView = () => {
    const c = Math.cos(view.elevation);
    camera.position.set(view.target.x + view.distance * c * Math.cos(view.azimuth),
                        view.target.y + view.distance * c * Math.sin(view.azimuth),
                        view.target.z + view.distance * Math.sin(view.elevation));
    camera.lookAt(view.target);
    draw();
  };
  const usePreset = (name) => {
    const preset = data.cameras[name];
    if (!preset) return;
    const eye = new THREE.Vector3(...preset.eye);
    view.target.set(...preset.target);
    const d = eye.clone().sub(view.target);
    view.distance = d.length();
    view.elevation = Math.asin(Math.max(-0.999, Math.min(0.999, d.z / view.distance)));
    view.azimuth = Math.atan2(d.y, d.x);
    camera.fov = preset.fov;
    camera.updateProjectionMatrix();
    applyView();
  };
  const cameraBar = document.getElementById("cameras");
  for (const name of Object.keys(data.cameras)) {
    const button = element("button", { "data-camera": name }, name);
    button.addEventListener("click", () => usePreset(name));
    cameraBar.append(button);
  }
  let drag = null;
  canvas.addEventListener("pointerdown", (e) => {
    drag = { x: e.clientX, y: e.clientY, pan: e.button === 2 || e.shiftKey };
    canvas.setPointerCapture(e.pointerId);
  });
  canvas.addEventListener("pointerup", () => { drag = null; });
  canvas.addEventListener("contextmenu", (e) => e.preventDefault());
  canvas.addEventListener("pointermove", (e) => {
    if (!drag) return;
    const dx = e.clientX - drag.x, dy = e.clientY - drag.y;
    drag.x = e.clientX; drag.y = e.clientY;
    if (drag.pan) {
      const scale = view.distance * 0.0015;
      const right = new THREE.Vector3().setFromMatrixColumn(camera.matrixWorld, 0);
      const up = new THREE.Vector3().setFromMatrixColumn(camera.matrixWorld, 1);
      view.target.addScaledVector(right, -dx * scale).addScaledVector(up, dy * scale);
    } else {
      view.azimuth -= dx * 0.008;
      view.elevation = Math.max(-1.5, Math.min(1.5, view.elevation + dy * 0.008));
    }
    applyView();
  });
  canvas.addEventListener("wheel", (e) => {
    e.preventDefault();
    view.distance = Math.max(0.2, Math.min(30, view.distance * Math.exp(e.deltaY * 0.001)));
    applyView();
  }, { passive: false });

  // time
  let time = 0, playing = false, speed = 1, last = null;
  const scrub = document.getElementById("scrub");
  scrub.max = String(duration);
  const clock = document.getElementById("clock");
  const playhead = document.getElementById("playhead");
  const lanesBox = document.getElementById("lanes");

  function pose(at) {
    for (let r = 0; r < robotNames.length; ++r) {
      for (let l = 0; l < data.links.length; ++l) {
        place(links[r][l], poseAt(linkPoses, linkStride, (r * data.links.length + l) * 7, at));
      }
    }
    objects.forEach((mesh, o) => place(mesh, poseAt(objectPoses, objectStride, o * 7, at)));
  }

  function draw() {
    const width = canvas.clientWidth, height = canvas.clientHeight;
    if (canvas.width !== Math.floor(width * renderer.getPixelRatio()) ||
        canvas.height !== Math.floor(height * renderer.getPixelRatio())) {
      renderer.setSize(width, height, false);
      camera.aspect = width / Math.max(1, height);
      camera.updateProjectionMatrix();
    }
    renderer.render(scene, camera);
  }

  function seek(t) {
    time = Math.max(0, Math.min(duration, t));
    pose(sampleAt(times, time));
    scrub.value = String(time);
    clock.textContent = `${fixed(time)} / ${fixed(duration)} s`;
    playhead.style.left = `calc(70px + (100% - 70px) * ${duration > 0 ? time / duration : 0})`;
    drawPlots();
    draw();
  }

  // plots of the chosen robot's tracking error, effort and grip force against their limits
  const plotSpecs = [["tracking_error", "tracking error [rad]"], ["effort_ratio", "effort / limit"],
                     ["grip_force", "grip force [N]"]];
  let plotRobot = 0;
  let plotCanvases = [];
  function plots(r) {
    plotRobot = r;
    const box = element("div", { id: "plots", "data-robot": robotNames[r] });
    const choose = element("p", {}, "plots of ");
    robotNames.forEach((name, k) => {
      const button = element("button", { "data-plot-robot": name }, name);
      button.disabled = k === r;
      button.addEventListener("click", () => box.replaceWith(plots(k)));
      choose.append(button, " ");
    });
    box.append(choose);
    plotCanvases = plotSpecs.map(([name, label]) => {
      const canvas = element("canvas", { width: "370", height: "80", "data-signal": name, title: label });
      box.append(element("div", {}, label), canvas);
      return canvas;
    });
    requestAnimationFrame(drawPlots);
    return box;
  }
  function drawPlots() {
    for (const canvas of plotCanvases) {
      if (!canvas.isConnected) continue;
      const name = canvas.dataset.signal, values = signals[name], limit = data.limits[name];
      let top = limit;
      for (let i = plotRobot; i < values.length; i += robotNames.length) top = Math.max(top, values[i]);
      top *= 1.1;
      const g = canvas.getContext("2d"), w = canvas.width, h = canvas.height;
      g.clearRect(0, 0, w, h);
      g.fillStyle = "#f6f6f3";
      g.fillRect(0, 0, w, h);
      g.strokeStyle = "#d03a2f";
      g.setLineDash([4, 3]);
      g.beginPath();
      g.moveTo(0, h - (limit / top) * h);
      g.lineTo(w, h - (limit / top) * h);
      g.stroke();
      g.setLineDash([]);
      g.strokeStyle = "#2b6cb0";
      g.beginPath();
      signalPolyline(times, values, robotNames.length, plotRobot, duration, top, w, h)
        .forEach(([x, y], i) => (i ? g.lineTo(x, y) : g.moveTo(x, y)));
      g.stroke();
      g.strokeStyle = "#1b1b1b";
      const x = duration > 0 ? (time / duration) * w : 0;
      g.beginPath();
      g.moveTo(x, 0);
      g.lineTo(x, h);
      g.stroke();
      g.fillStyle = "#444";
      g.fillText(`limit ${Number(limit).toPrecision(3)}, top ${Number(top / 1.1).toPrecision(3)}`, 4, 11);
    }
  }

  const playButton = document.getElementById("play");
  const setPlaying = (on) => {
    playing = on && duration > 0;
    playButton.textContent = playing ? "Pause" : "Play";
    last = null;
    if (playing) requestAnimationFrame(tick);
  };
  function tick(now) {
    if (!playing) return;
    if (last !== null) {
      const next = time + (now - last) / 1000 * speed;
      seek(next >= duration ? duration : next);
      if (next >= duration) { setPlaying(false); return; }
    }
    last = now;
    requestAnimationFrame(tick);
  }
  playButton.addEventListener("click", () => {
    if (!playing && time >= duration) seek(0);
    setPlaying(!playing);
  });
  document.addEventListener("keydown", (e) => {
    if (e.code === "Space" && e.target.tagName !== "INPUT") { e.preventDefault(); playButton.click(); }
  });
  const speeds = document.getElementById("speed");
  for (const s of [0.25, 0.5, 1, 2, 4, 8]) speeds.append(element("option", { value: String(s) }, `${s}x`));
  speeds.value = "1";
  speeds.addEventListener("change", () => { speed = Number(speeds.value); });
  scrub.addEventListener("input", () => { setPlaying(false); seek(Number(scrub.value)); });
  window.addEventListener("resize", draw);

  // timeline: a lane per robot, the events' lane below
  const details = document.getElementById("details");
  const bars = [];
  for (const lane of laneLayout(robotNames, report.actions, duration)) {
    const row = element("div", { class: "lane", "data-robot": lane.robot });
    row.append(element("span", { class: "label" }, lane.robot));
    for (const bar of lane.bars) {
      const action = report.actions[bar.index];
      const box = element("div", { class: "bar " + (action.passed ? "passed" : "failed"), "data-action": String(bar.index),
                                   title: action.id + (action.passed ? "" : ": " + action.failure) }, action.id);
      box.style.left = `${bar.left * 100}%`;
      box.style.width = `${bar.width * 100}%`;
      box.addEventListener("click", (e) => { e.stopPropagation(); selectAction(bar.index); });
      bars.push(box);
      row.append(box);
    }
    row.addEventListener("click", (e) => seek((e.offsetX / row.clientWidth) * duration));
    lanesBox.append(row);
  }
  const eventRow = element("div", { class: "lane", "data-robot": "" });
  eventRow.append(element("span", { class: "label" }, "events"));
  report.events.forEach((event, index) => {
    const mark = element("div", { class: "event", "data-event": String(index), title: `${event.kind}: ${event.detail}` });
    mark.style.left = `${duration > 0 ? (event.t / duration) * 100 : 0}%`;
    mark.addEventListener("click", (e) => { e.stopPropagation(); selectEvent(index); });
    eventRow.append(mark);
  });
  lanesBox.append(eventRow);

  function table(rows, headings) {
    const t = element("table");
    const head = element("tr");
    for (const h of headings) head.append(element("th", {}, h));
    t.append(head);
    for (const cells of rows) {
      const tr = element("tr");
      for (const cell of cells) tr.append(cell);
      t.append(tr);
    }
    return t;
  }
  const cell = (text, cls = "") => element("td", cls ? { class: cls } : {}, text);

  function showOverview() {
    details.replaceChildren(element("h2", {}, "Run"));
    details.append(element("p", {}, "Click an action or an event on the timeline to see its checks."));
    details.append(table(report.robots.map((r) => [cell(r.robot), cell(fixed(r.max_tracking_error, 4), "num"),
                                                    cell(fixed(r.max_effort_ratio, 2), "num"),
                                                    cell(fixed(r.max_tcp_force, 1), "num")]),
                         ["robot", "max tracking [rad]", "max effort / limit", "max TCP force [N]"]));
    const failed = report.readiness.filter((c) => !c.passed);
    details.append(element("h2", { class: failed.length ? "failed" : "passed" },
                           failed.length ? "Hardware readiness: not ready" : "Hardware readiness: ready"));
    details.append(table(report.readiness.map((c) => [cell(c.name), cell(c.subject),
                                                       cell(`${Number(c.value).toPrecision(4)} / ${Number(c.limit).toPrecision(4)} ${c.unit}`, "num"),
                                                       cell(c.passed ? "ok" : "FAIL", c.passed ? "passed" : "failed")]),
                         ["check", "subject", "value / limit", ""]));
    details.append(plots(plotRobot));
  }

  function selectAction(index) {
    const action = report.actions[index];
    bars.forEach((b) => b.classList.toggle("selected", Number(b.dataset.action) === index));
    setPlaying(false);
    seek(action.passed ? action.start : failureTime(action));
    details.replaceChildren(element("h2", { class: action.passed ? "passed" : "failed" }, action.id));
    details.append(element("p", {}, `planned ${fixed(action.start)}-${fixed(action.end)} s: ` +
                                    (action.passed ? "passed" : "FAILED: " + action.failure)));
    if (action.measurements.length) {
      const measured = (m) => (m.text.startsWith(m.name + " ") ? m.text.slice(m.name.length + 1) : m.text);
      details.append(table(action.measurements.map((m) => [cell(m.name), cell(measured(m), "num"),
                                                            cell(m.passed ? "ok" : "FAIL", m.passed ? "passed" : "failed")]),
                           ["check", "measured", ""]));
    }
    details.append(plots(Math.max(0, robotNames.indexOf(action.robots[0]))));
    const related = report.events.filter((e) => e.action === action.id);
    if (related.length) details.append(element("p", {}, "events: " + related.map((e) => `${fixed(e.t)} s ${e.kind}`).join("; ")));
    const object = objects.find((o) => o.userData.name === action.object);
    marker.visible = !action.passed && object !== undefined;
    if (marker.visible) marker.position.copy(object.position);
    details.dataset.action = String(index);
    draw();
  }
  // where a failed action is best seen: its first event within it, else its start
  const failureTime = (action) =>
    report.events.find((e) => e.action === action.id && e.t >= action.start && e.t <= action.end)?.t ?? action.start;

  function selectEvent(index) {
    const event = report.events[index];
    setPlaying(false);
    seek(event.t);
    marker.visible = true;
    marker.position.set(...event.where);
    details.replaceChildren(element("h2", { class: "failed" }, event.kind));
    details.append(element("p", {}, `${fixed(event.t)} s: ${event.detail}` + (event.action ? ` (during ${event.action})` : "")));
    details.append(plots(plotRobot));
    draw();
  }

  // start: the fragment's time, camera and action, if any
  const settings = fragmentSettings(window.location.hash);
  usePreset(settings.camera in data.cameras ? settings.camera : "oblique");
  showOverview();
  seek(Number(settings.t) || 0);
  if (settings.action !== undefined) selectAction(Number(settings.action));
  document.body.dataset.requests = String(performance.getEntriesByType("resource").length);
  document.body.dataset.ready = "1";
  // for scripts driving the page (tests/replay/browser.test.js)
  window.dashbedReplay = { seek, selectAction, selectEvent, usePreset, draw, camera, links, data,
                           get time() { return time; }, get playing() { return playing; } };
}

if (typeof module !== "undefined" && module.exports) {
  module.exports = { decodeBase64, decodeArray, decodePoses, sampleAt, poseAt, laneLayout, signalPolyline,
                     fragmentSettings };
} else {
  main();
}
