// A real browser against `plexus launch --monitor` (tests/ecosystem/monitor_rfid.sh):
//   node monitor_check.mjs URL OUT_DIR PROCESS_TO_KILL
// Drives Debian's chromium, headless, with puppeteer-core, on the monitor's page (URL), and
// checks what a user would look at:
//   1. every process's row turns up ok, then shows a live heartbeat: a loop count that grows
//      over 1.5 s, health ok or degraded (the names go to OUT_DIR/page.json, for the script
//      to compare with the launcher's own list in launch.json);
//   2. the plot's data grows (its point count, 2 s apart);
//   3. SIGKILL sent here to PROCESS_TO_KILL (the pid its row shows) turns its row red
//      ("down") within 2 s, measured from the kill to the page in the browser, and the row
//      comes back ("ok", restarts >= 1) after the launcher restarts it.
// A screenshot of the page is kept as OUT_DIR/monitor.png (after the restart).
// Exit 1 on a failed check, with one line per failure.
import puppeteer from "puppeteer-core";
import { writeFileSync } from "node:fs";

const [url, outDir, victim] = process.argv.slice(2);
if (!url || !outDir || !victim) {
  console.error("usage: node monitor_check.mjs URL OUT_DIR PROCESS_TO_KILL");
  process.exit(2);
}
const failures = [];
const result = {};
const sleep = (ms) => new Promise((r) => setTimeout(r, ms));

const browser = await puppeteer.launch({
  executablePath: process.env.CHROMIUM || "/usr/bin/chromium",
  headless: true,
  // Root in CI: no sandbox. Nothing leaves the machine: no proxy lookup, no background services.
  args: ["--no-sandbox", "--disable-gpu", "--no-proxy-server", "--disable-background-networking",
         "--disable-component-update", "--disable-domain-reliability", "--disable-sync", "--no-first-run"],
});
try {
  const page = await browser.newPage();
  await page.setViewport({ width: 1500, height: 1000 });
  page.on("pageerror", (e) => failures.push(`page error: ${e.message}`));
  // The launcher listens before it starts any process; still, give it a moment.
  for (let i = 0; ; ++i) {
    try {
      await page.goto(url, { waitUntil: "load", timeout: 5000 });
      break;
    } catch (e) {
      if (i >= 20) throw new Error(`cannot open ${url}: ${e.message}`);
      await sleep(500);
    }
  }
  const rows = () =>
    page.$$eval("#processes tbody tr", (trs) =>
      trs.map((r) => ({ name: r.dataset.process, health: r.dataset.health, loops: Number(r.dataset.loops),
                        pid: Number(r.dataset.pid), restarts: Number(r.dataset.restarts),
                        downAt: r.dataset.downAt })));
  const phase = () => page.$eval("#phase", (e) => e.textContent);

  // 1. Every process up and running, its loop count growing.
  const upBy = Date.now() + 40000;
  let first = [];
  while (Date.now() < upBy) {
    first = await rows();
    if ((await phase()) === "running" && first.length > 0 && first.every((r) => r.health === "ok")) break;
    await sleep(200);
  }
  if (!(first.length > 0 && first.every((r) => r.health === "ok")))
    failures.push(`not every process ok within 40 s: ${JSON.stringify(first.map((r) => [r.name, r.health]))}`);
  await sleep(1500);
  const later = await rows();
  for (const r of first) {
    const l = later.find((x) => x.name === r.name);
    if (!l || !(l.loops > r.loops)) failures.push(`${r.name}: no live heartbeat (loops ${r.loops} -> ${l?.loops})`);
  }
  // Live: its heartbeat's loop count grew, and the page does not show it down or starting.
  // Degraded (a held output since its last heartbeat: an input late, as on a loaded machine)
  // is live; the health the page showed is kept beside the names.
  const live = later.filter((r) => {
    const f = first.find((x) => x.name === r.name);
    return f && r.loops > f.loops && (r.health === "ok" || r.health === "degraded");
  });
  result.processes = live.map((r) => r.name).sort();
  result.health = Object.fromEntries(later.map((r) => [r.name, r.health]));

  // 2. The plot grows.
  const points = () => page.$eval("#plot", (e) => Number(e.dataset.points));
  const p0 = await points();
  await sleep(2000);
  const p1 = await points();
  result.plot_points = [p0, p1];
  if (!(p1 > p0 && p0 > 0)) failures.push(`the plot did not grow: ${p0} -> ${p1} points`);

  // 3. Kill one service; its row turns red within 2 s, then comes back after the restart.
  const target = (await rows()).find((r) => r.name === victim || r.name.endsWith(" " + victim));
  if (!target || !(target.pid > 0)) {
    failures.push(`no row with a pid for ${victim}`);
  } else {
    const killedAt = Date.now();
    process.kill(target.pid, "SIGKILL");
    const isDown = (name) =>
      document.querySelector(`#processes tr[data-process="${CSS.escape(name)}"]`)?.dataset.health === "down";
    try {
      await page.waitForFunction(isDown, { timeout: 2000, polling: 20 }, target.name);
      result.red_after_s = (Date.now() - killedAt) / 1000;
    } catch {
      failures.push(`${target.name}: not red within 2 s of its SIGKILL`);
    }
    const isBack = (name) => {
      const r = document.querySelector(`#processes tr[data-process="${CSS.escape(name)}"]`);
      return r?.dataset.health === "ok" && Number(r.dataset.restarts) >= 1;
    };
    try {
      await page.waitForFunction(isBack, { timeout: 15000, polling: 50 }, target.name);
      result.back_after_s = (Date.now() - killedAt) / 1000;
    } catch {
      failures.push(`${target.name}: not back (ok, restarted) within 15 s of its SIGKILL`);
    }
  }
  await page.screenshot({ path: `${outDir}/monitor.png`, fullPage: true });
} catch (e) {
  failures.push(e.message);
} finally {
  await browser.close();
}
result.failures = failures;
writeFileSync(`${outDir}/page.json`, JSON.stringify(result, null, 2) + "\n");
console.log(JSON.stringify(result));
for (const f of failures) console.log("FAIL: " + f);
process.exit(failures.length ? 1 : 0);
