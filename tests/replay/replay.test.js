// The replay page's pure functions (assets/web/replay.js) under Node's test runner.
"use strict";
const test = require("node:test");
const assert = require("node:assert/strict");
const path = require("node:path");
const replay = require(path.join(__dirname, "../../assets/web/replay.js"));

test("base64 decodes to the bytes written, in the typed array asked for", () => {
  const floats = new Float32Array([1.5, -2.25, 1e-3]);
  const text = Buffer.from(floats.buffer).toString("base64");
  assert.deepEqual(Array.from(replay.decodeArray(text, Float32Array)), Array.from(floats));
  assert.equal(replay.decodeBase64("").byteLength, 0);
  assert.deepEqual(Array.from(replay.decodeArray("AQID", Uint8Array)), [1, 2, 3]);
});

test("quantised poses come back in metres and unit quaternions", () => {
  const raw = new Int16Array([12000, -5, 32767, 0, 0, 23170, 23170]);
  const poses = replay.decodePoses(Buffer.from(raw.buffer).toString("base64"), 1e-4);
  assert.ok(Math.abs(poses[0] - 1.2) < 1e-6 && Math.abs(poses[1] + 5e-4) < 1e-9 && Math.abs(poses[2] - 3.2767) < 1e-6);
  const norm = Math.hypot(poses[3], poses[4], poses[5], poses[6]);
  assert.ok(Math.abs(norm - 1) < 1e-4);
});

test("sampleAt brackets a time and clamps outside the samples", () => {
  const times = new Float32Array([0, 0.5, 1.0, 1.5]);
  assert.deepEqual(replay.sampleAt(times, -1), { i: 0, j: 0, f: 0 });
  assert.deepEqual(replay.sampleAt(times, 9), { i: 3, j: 3, f: 0 });
  assert.deepEqual(replay.sampleAt(times, 0.75), { i: 1, j: 2, f: 0.5 });
  assert.deepEqual(replay.sampleAt(times, 1.0), { i: 2, j: 3, f: 0 });
  assert.deepEqual(replay.sampleAt(new Float32Array(0), 1), { i: 0, j: 0, f: 0 });
});

test("poseAt interpolates positions linearly and rotations along the shorter arc", () => {
  const s = Math.SQRT1_2;
  // two samples of one pose: from the origin, identity, to (2, 0, 0) turned 90 degrees about z,
  // the second written with the quaternion's other sign
  const poses = [0, 0, 0, 0, 0, 0, 1, 2, 0, 0, 0, 0, -s, -s];
  const half = replay.poseAt(poses, 7, 0, { i: 0, j: 1, f: 0.5 });
  assert.ok(Math.abs(half[0] - 1) < 1e-12);
  const angle = 2 * Math.atan2(Math.abs(half[5]), Math.abs(half[6]));
  assert.ok(Math.abs(angle - Math.PI / 4) < 1e-9, `half-way angle ${angle}`);
  assert.ok(Math.abs(Math.hypot(half[3], half[4], half[5], half[6]) - 1) < 1e-12);
});

test("every action gets a bar in each of its robots' lanes", () => {
  const actions = [
    { robots: ["r0"], start: 0, end: 2 },
    { robots: ["r0", "r1"], start: 2, end: 6 },
    { robots: ["r1"], start: 6, end: 10 },
  ];
  const lanes = replay.laneLayout(["r0", "r1"], actions, 10);
  assert.deepEqual(lanes.map((l) => l.bars.map((b) => b.index)), [[0, 1], [1, 2]]);
  assert.deepEqual(lanes[1].bars[1], { index: 2, left: 0.6, width: 0.4 });
  assert.equal(replay.laneLayout(["r0"], [], 0)[0].bars.length, 0);
});

test("a robot's signal is drawn against time, clipped at the top", () => {
  const times = new Float32Array([0, 5, 10]);
  const values = new Float32Array([0, 9, 2, 9, 4, 99]);  // [sample][robot], two robots
  assert.deepEqual(replay.signalPolyline(times, values, 2, 0, 10, 4, 100, 50), [[0, 50], [50, 25], [100, 0]]);
  assert.deepEqual(replay.signalPolyline(times, values, 2, 1, 10, 9, 100, 50).map((p) => p[1]), [0, 0, 0]);
});

test("the fragment sets time, camera and action", () => {
  assert.deepEqual(replay.fragmentSettings("#t=16.5&camera=side%3Ar1&paused"), { t: "16.5", camera: "side:r1", paused: true });
  assert.deepEqual(replay.fragmentSettings(""), {});
});
