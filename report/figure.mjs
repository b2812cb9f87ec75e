// A figure (PNG) of chosen channels of a run, drawn by the report bundle in headless chromium:
//   node report/figure.mjs OUTDIR/report.html 'pendulum.joint*.q' [more globs] -o figure.png \
//     [--scale 57.29577951308232] [--ylabel 'joint angle [deg]'] [--title T] [--width 760 --height 360]
// The channels must be recorded (timeseries.csv); the page is the run's report.html.
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { pathToFileURL } from 'node:url';
import puppeteer from 'puppeteer-core';

const args = process.argv.slice(2);
const opt = name => { const i = args.indexOf(name); return i >= 0 ? args.splice(i, 2)[1] : undefined; };
const output = opt('-o'), chromium = opt('--chromium') || process.env.CHROMIUM || '/usr/bin/chromium';
const fig = { scale: Number(opt('--scale') || 1), ylabel: opt('--ylabel'), title: opt('--title'),
  width: Number(opt('--width') || 760), height: Number(opt('--height') || 360) };
const [page, ...channels] = args;
if (!page || !output || !channels.length) {
  console.error("usage: node report/figure.mjs OUTDIR/report.html GLOB... -o figure.png [--scale S] [--ylabel L] [--title T]");
  process.exit(2);
}
fig.channels = channels;
const profile = mkdtempSync(join(tmpdir(), 'yardsim-figure-'));
const browser = await puppeteer.launch({
  executablePath: chromium, headless: true,
  args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
    '--disable-background-networking', '--disable-component-update', '--disable-sync',
    '--disable-dev-shm-usage', '--enable-unsafe-swiftshader', `--user-data-dir=${profile}`],
});
let status = 0;
try {
  const tab = await browser.newPage();
  await tab.setViewport({ width: fig.width + 100, height: fig.height + 200, deviceScaleFactor: 1 });
  await tab.evaluateOnNewDocument(f => { window.yardsimFigure = f; }, fig);
  await tab.goto(pathToFileURL(resolve(page)).href);
  await tab.waitForFunction(() => window.yardsim && (window.yardsim.ready || window.yardsim.error));
  const error = await tab.evaluate(() => window.yardsim.error);
  if (error) throw new Error(error);
  await (await tab.$('#figure')).screenshot({ path: output });
  console.log(output);
} catch (e) {
  console.error(String(e.message || e));
  status = 1;
} finally {
  await browser.close();
  rmSync(profile, { recursive: true, force: true });
}
process.exit(status);
