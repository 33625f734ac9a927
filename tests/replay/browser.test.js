// The HTML replay in a real browser (Debian's chromium through puppeteer-core), used as a person
// would: the default world's run and a run whose pick fails. Needs DASHBED_CLI (the dashbed
// binary) and CHROMIUM (the browser); writes into REPLAY_DIR.
"use strict";
const test = require("node:test");
const assert = require("node:assert/strict");
const fs = require("node:fs");
const path = require("node:path");
const { execFileSync } = require("node:child_process");
const { pathToFileURL } = require("node:url");

const root = path.join(__dirname, "../..");
const puppeteer = require(path.join(root, "assets/web/node_modules/puppeteer-core"));
const cli = process.env.DASHBED_CLI;
const chromium = process.env.CHROMIUM || "/usr/bin/chromium";
const dir = process.env.REPLAY_DIR || fs.mkdtempSync("/tmp/replay-");
fs.mkdirSync(dir, { recursive: true });

function dashbed(...args) {
  return execFileSync(cli, args, { cwd: dir, encoding: "utf8", stdio: ["ignore", "pipe", "pipe"] });
}

/** A run's files: the plan, its report and its replay; `edit` changes the plan first. */
function run(name, edit) {
  dashbed("plan", "-o", `${name}.json`);
  if (edit) {
    const plan = JSON.parse(fs.readFileSync(path.join(dir, `${name}.json`), "utf8"));
    edit(plan);
    fs.writeFileSync(path.join(dir, `${name}.json`), JSON.stringify(plan));
  }
  try {
    dashbed("sim", `${name}.json`, "--report", `${name}.report.json`, "--html", `${name}.html`, "--quiet");
  } catch (e) {
    if (e.status !== 1) throw e;  // 1: a check failed, as asked
  }
  return { report: JSON.parse(fs.readFileSync(path.join(dir, `${name}.report.json`), "utf8")),
           html: path.join(dir, `${name}.html`) };
}

/** Opens a replay with every request but the page itself refused and recorded. */
async function open(browser, file, fragment = "") {
  const page = await browser.newPage();
  await page.setViewport({ width: 1280, height: 800 });
  const requests = [], errors = [];
  await page.setRequestInterception(true);
  const own = pathToFileURL(file).href;
  page.on("request", (request) => {
    if (request.url().split("#")[0] === own) return request.continue();
    requests.push(request.url());
    request.abort();
  });
  page.on("pageerror", (error) => errors.push(String(error)));
  page.on("console", (message) => { if (message.type() === "error") errors.push(message.text()); });
  await page.goto(own + fragment, { waitUntil: "load" });
  await page.waitForSelector("body[data-ready='1']", { timeout: 20000 });
  return { page, requests, errors };
}

let browser;
test.before(async () => {
  browser = await puppeteer.launch({
    executablePath: chromium,
    headless: true,
    args: ["--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader"],
  });
});
test.after(async () => { if (browser) await browser.close(); });

test("the default run: offline, the scene drawn, every action on the timeline, camera and playback", async () => {
  const { report, html } = run("default");
  assert.ok(fs.statSync(html).size <= 3 * 1024 * 1024, "the default run's replay is at most 3 MB");
  const { page, requests, errors } = await open(browser, html, "#t=16&camera=oblique");
  assert.deepEqual(requests, [], "nothing fetched");
  assert.deepEqual(errors, [], "no script errors");

  // every action of the report, each robot's in its lane
  const bars = await page.$$eval(".bar", (nodes) => nodes.map((n) => ({ index: Number(n.dataset.action), text: n.textContent,
                                                                          robot: n.parentElement.dataset.robot })));
  assert.deepEqual([...new Set(bars.map((b) => b.index))].sort((a, b) => a - b), report.actions.map((_, i) => i));
  for (const bar of bars) assert.ok(report.actions[bar.index].robots.includes(bar.robot));
  assert.equal(await page.$eval("header .verdict", (n) => n.textContent), "PASSED");

  // the robot is drawn where its wrist is: the pixel there changes when the robots are hidden
  const probe = await page.evaluate(() => {
    const replay = window.dashbedReplay;
    const wrist = replay.data.links.findIndex((l) => l.name === "wrist_3_link");
    const mesh = replay.links[0][wrist];
    mesh.updateMatrixWorld();
    const p = mesh.position.clone().project(replay.camera);
    const canvas = document.getElementById("scene");
    const box = canvas.getBoundingClientRect();
    return { x: Math.round(box.left + (p.x + 1) / 2 * box.width), y: Math.round(box.top + (1 - p.y) / 2 * box.height),
             inside: Math.abs(p.x) < 1 && Math.abs(p.y) < 1 };
  });
  assert.ok(probe.inside, "r0's wrist is in view");
  const pixel = async () => {
    const shot = await page.screenshot({ clip: { x: probe.x - 1, y: probe.y - 1, width: 3, height: 3 }, encoding: "base64" });
    return shot;
  };
  const withRobots = await pixel();
  await page.evaluate(() => { for (const robot of window.dashbedReplay.links) for (const m of robot) m.visible = false;
                              window.dashbedReplay.draw(); });
  const withoutRobots = await pixel();
  assert.notEqual(withRobots, withoutRobots, "robot pixels at r0's wrist");
  await page.evaluate(() => { for (const robot of window.dashbedReplay.links) for (const m of robot) m.visible = true;
                              window.dashbedReplay.draw(); });

  // the scene is not blank: many colours in the canvas
  const shot = await page.screenshot({ encoding: "binary", clip: { x: 0, y: 40, width: 860, height: 600 } });
  assert.ok(shot.length > 20000, `a screenshot of the scene has detail (${shot.length} bytes)`);

  // camera presets move the camera; playing advances time
  const before = await page.evaluate(() => window.dashbedReplay.camera.position.toArray());
  await page.click("button[data-camera='top']");
  const after = await page.evaluate(() => window.dashbedReplay.camera.position.toArray());
  assert.notDeepEqual(after, before);
  assert.ok(after[2] > before[2], "the top view looks down from above");
  const t0 = await page.evaluate(() => window.dashbedReplay.time);
  await page.click("#play");
  await new Promise((resolve) => setTimeout(resolve, 400));
  await page.click("#play");
  assert.ok(await page.evaluate(() => window.dashbedReplay.time) > t0, "playing advances the time");
  fs.writeFileSync(path.join(dir, "default.png"), shot);
  await page.close();

  // the saved run's replay, written again from its report, is the same file
  dashbed("view", "default.report.json", "-o", "view.html");
  assert.ok(fs.readFileSync(path.join(dir, "view.html")).equals(fs.readFileSync(html)), "dashbed view writes the same replay");
  // a report of another world is refused
  assert.throws(() => dashbed("view", "default.report.json", "--world", path.join(root, "worlds/shelf_2r_4o.yaml"),
                              "-o", "other.html"), /is a run of world/);
  assert.ok(!fs.existsSync(path.join(dir, "other.html")));
});

test("a failing run: clicking the failed action shows its failing check", async () => {
  // r0's gripper never closes: its first pick fails
  const { report, html } = run("no_close", (plan) => {
    plan.gripper = plan.gripper.filter((c) => !(c.robot === "r0" && c.command === "close"));
  });
  const failed = report.actions.findIndex((a) => a.verdict === "failed");
  assert.ok(failed >= 0, "the edited plan fails");
  const { page, requests, errors } = await open(browser, html);
  assert.deepEqual(requests, []);
  assert.deepEqual(errors, []);
  assert.equal(await page.$eval("header .verdict", (n) => n.textContent), "FAILED");
  await page.click(`.bar.failed[data-action='${failed}']`);
  const shown = await page.$eval("#details", (n) => ({ title: n.querySelector("h2").textContent, text: n.textContent }));
  assert.equal(shown.title, report.actions[failed].id);
  assert.ok(shown.text.includes(report.actions[failed].failure), "the failure text is shown");
  // the acting robot's tracking, effort and grip force are plotted beside it
  const plotted = await page.$eval("#plots", (n) => ({ robot: n.dataset.robot,
                                                       signals: [...n.querySelectorAll("canvas")].map((c) => c.dataset.signal) }));
  assert.equal(plotted.robot, report.actions[failed].robots[0]);
  assert.deepEqual(plotted.signals, ["tracking_error", "effort_ratio", "grip_force"]);
  const time = await page.evaluate(() => window.dashbedReplay.time);
  const planned = report.actions[failed].planned;
  assert.ok(time >= planned.start - 1e-6 && time <= planned.end + 1e-6,
            "the replay jumped to the failed action");
  await page.screenshot({ path: path.join(dir, "no_close.png") });
  await page.close();
});

test("a stress campaign's page: rates, and each worst trial's replay one click away", async () => {
  const world = path.join(root, "tests/python/one_cube.yaml");
  dashbed("stress", world, "-n", "3", "--sweep", "0.002,0.03", "--worst", "2", "--out", "stress", "--html",
          "stress.html", "-j", "2");
  const summary = JSON.parse(fs.readFileSync(path.join(dir, "stress/summary.json"), "utf8"));
  const page = await browser.newPage();
  const requests = [];
  await page.setRequestInterception(true);
  page.on("request", (request) => {
    if (request.isNavigationRequest() && request.url().startsWith("file://")) return request.continue();
    requests.push(request.url());
    request.abort();
  });
  await page.goto(pathToFileURL(path.join(dir, "stress.html")).href, { waitUntil: "load" });
  assert.equal(await page.$$eval("#rate-plot circle.point", (n) => n.length), summary.points.length);
  const rates = await page.$$eval("#points tr td:nth-child(3)", (n) => n.map((c) => c.textContent));
  assert.deepEqual(rates, summary.points.map((p) => `${(100 * p.success_rate).toFixed(1)} %`));
  const links = await page.$$eval("#worst a", (n) => n.map((a) => a.getAttribute("href")));
  assert.equal(links.length, summary.worst_trials.length);
  assert.ok(links.length > 0, "a 3 cm offset fails some trial");
  await Promise.all([page.waitForNavigation({ waitUntil: "load" }), page.click("#worst a")]);
  await page.waitForSelector("body[data-ready='1']", { timeout: 20000 });
  assert.equal(await page.$eval("header .verdict", (n) => n.textContent), "FAILED");
  assert.deepEqual(requests, [], "nothing but the pages fetched");
  await page.close();
});
