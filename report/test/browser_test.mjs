// Opens a report.html in Debian's chromium (puppeteer-core, headless, no GPU, fresh profile)
// and checks what a person would: no console errors, no network requests, plots drawn, one
// mesh per body, the slider moves the block (or the most-travelled body) and the plot cursor (and the plot
// cursor moves the slider), one timeline row per actor; saves a screenshot. --bodies names the
// bodies the replay must show, each moving over the run (a scene's replay asserted present).
//   node test/browser_test.mjs OUTDIR/report.html SCREENSHOT.png [--chromium /usr/bin/chromium]
//     [--bodies block,FC.barge]
import { mkdtempSync, readFileSync, rmSync, existsSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join, resolve } from 'node:path';
import { pathToFileURL } from 'node:url';
import puppeteer from 'puppeteer-core';
import { groupSeries, maxAbs } from '../src/units.js';

const args = process.argv.slice(2);
const flag = name => { const i = args.indexOf(name); return i >= 0 ? args.splice(i, 2)[1] : undefined; };
const chromium = flag('--chromium') || process.env.CHROMIUM || '/usr/bin/chromium';
const required = (flag('--bodies') || '').split(',').filter(Boolean);
const [reportPath, screenshot] = args;
if (!reportPath || !screenshot) {
  console.error('usage: node test/browser_test.mjs OUTDIR/report.html SCREENSHOT.png [--chromium PATH]');
  process.exit(2);
}

let passed = 0, failed = 0;
function check(what, ok, detail = '') {
  if (ok) passed++; else failed++;
  console.log(`${ok ? 'ok  ' : 'FAIL'} ${what}${detail ? `: ${detail}` : ''}`);
}

// (report.html) => its data, and from replay.glb's own JSON the bodies and each one's travel
const html = readFileSync(reportPath, 'utf8');
const data = JSON.parse(html.match(/<script type="application\/json" id="yardsim-data">([\s\S]*?)<\/script>/)[1]);
const bodies = [];
if (data.glb) {
  const glb = Buffer.from(data.glb, 'base64');
  const jsonLength = glb.readUInt32LE(12);
  const gltf = JSON.parse(glb.subarray(20, 20 + jsonLength).toString('utf8'));
  const bin = glb.subarray(20 + jsonLength + 8);
  const floats = a => {
    const acc = gltf.accessors[a], view = gltf.bufferViews[acc.bufferView];
    return new Float32Array(bin.buffer.slice(bin.byteOffset + view.byteOffset, bin.byteOffset + view.byteOffset + view.byteLength));
  };
  gltf.nodes.forEach((node, i) => {
    // (a catenary line's profile marker: extras.body without a mesh) => not a body
    if (!node.extras || node.extras.body === undefined || node.mesh === undefined) return;
    const ch = gltf.animations[0].channels.find(c => c.target.node === i && c.target.path === 'translation');
    const p = floats(gltf.animations[0].samplers[ch.sampler].output);
    let travel = 0;
    for (let k = 3; k < p.length; k += 3) travel = Math.max(travel, Math.hypot(p[k] - p[0], p[k + 1] - p[1], p[k + 2] - p[2]));
    bodies.push({ name: node.extras.body, travel });
  });
}
// (trace.jsonl beside the report) => the actors that started, independently of the page
const actors = new Set((data.run && data.run.actors || []).map(a => a.path));
const trace = join(dirname(reportPath), 'trace.jsonl');
if (existsSync(trace))
  for (const line of readFileSync(trace, 'utf8').split('\n'))
    if (line.includes('"port":"started"')) actors.add(JSON.parse(line).model);

const profile = mkdtempSync(join(tmpdir(), 'yardsim-chromium-'));
const browser = await puppeteer.launch({
  executablePath: chromium,
  headless: true,
  args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
    '--disable-background-networking', '--disable-component-update', '--disable-sync',
    '--disable-dev-shm-usage', '--enable-unsafe-swiftshader', `--user-data-dir=${profile}`],
});
try {
  const page = await browser.newPage();
  await page.setViewport({ width: 1400, height: 1000 });
  const url = pathToFileURL(resolve(reportPath)).href;
  const errors = [], requests = [];
  page.on('console', m => { if (m.type() === 'error') errors.push(m.text()); });
  page.on('pageerror', e => errors.push(String(e)));
  page.on('request', r => { if (r.url() !== url) requests.push(r.url()); });
  const t0 = Date.now();
  await page.goto(url, { waitUntil: 'load' });
  await page.waitForFunction(() => window.yardsim && (window.yardsim.ready || window.yardsim.error), { timeout: 60000 });
  const ms = Date.now() - t0;
  const pageError = await page.evaluate(() => window.yardsim.error);
  check('the page is ready', !pageError, pageError || `${ms} ms`);
  if (data.kind === 'loglog') await checkLogLog(page);
  else if (data.kind === 'sweep') await checkSweep(page);
  else await checkReport(page);
  if (data.kind !== 'loglog' && data.kind !== 'sweep' && data.series.length) await checkFigure(url);
  check('no console errors', errors.length === 0, errors.join(' | '));
  check('no network requests', requests.length === 0, requests.join(' '));
  await page.screenshot({ path: screenshot, fullPage: true });
  check('screenshot saved', existsSync(screenshot), screenshot);
} finally {
  await browser.close();
  rmSync(profile, { recursive: true, force: true });
}
console.log(`${passed} passed, ${failed} failed`);
process.exit(failed ? 1 : 0);

// (uPlot canvases) => pixels drawn in each
function drawnPixels(page) {
  return page.evaluate(() => [...document.querySelectorAll('.uplot canvas')].map(c => {
    const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    let n = 0;
    for (let i = 3; i < d.length; i += 4) if (d[i] > 0) n++;
    return n;
  }));
}

// (figure mode, as report/figure.mjs uses it) => one chart of the first channel, scaled by 2
async function checkFigure(url) {
  const tab = await browser.newPage();
  const first = data.series[0].name;
  await tab.evaluateOnNewDocument(n => { window.yardsimFigure = { channels: [n], scale: 2, ylabel: 'twice' }; }, first);
  await tab.goto(url);
  await tab.waitForFunction(() => window.yardsim && (window.yardsim.ready || window.yardsim.error));
  const f = await tab.evaluate(() => {
    const u = window.yardsim.plots && window.yardsim.plots[0];
    return u ? { series: u.series.length - 1, first: u.data[1][u.data[1].length - 1], figure: !!document.getElementById('figure') } : { error: window.yardsim.error };
  });
  const raw = Buffer.from(data.series[0].data, 'base64');
  const values = new Float32Array(raw.buffer.slice(raw.byteOffset, raw.byteOffset + raw.length));
  check('figure mode draws the chosen channel, scaled', f.figure && f.series === 1 && Math.abs(f.first - 2 * values[values.length - 1]) <= 1e-6 * Math.abs(f.first) + 1e-30,
    JSON.stringify(f));
  await tab.close();
}

// (wp.html) => one log-log chart per plot with its curves, drawn, log scales
async function checkLogLog(page) {
  const drawn = await drawnPixels(page);
  check('one chart per plot, each with drawn pixels', drawn.length === data.plots.length && drawn.every(n => n > 500), `pixels ${drawn.join(', ')}`);
  const charts = await page.evaluate(() => window.yardsim.plots.map(u => ({ series: u.series.length - 1, distr: [u.scales.x.distr, u.scales.y.distr] })));
  check('one series per curve, log-log', charts.every((c, i) => c.series === data.plots[i].curves.length && c.distr[0] === 3 && c.distr[1] === 3),
    JSON.stringify(charts));
}

// (sweep.html) => the case table sorts and filters, one plot per collected quantity and varied
// parameter with its limit line, and the operability map with a point per case run
async function checkSweep(page) {
  const rows = () => page.evaluate(() => [...document.querySelectorAll('#cases tbody tr')].map(tr => tr.children[0].textContent));
  const all = await rows();
  check('one table row per case', all.length === data.rows.length, `${all.length} rows, ${data.rows.length} cases`);
  await page.click('#cases th[data-col="0"]');
  await page.click('#cases th[data-col="0"]');
  const down = await rows();
  check('a click on a column sorts by it, a second one reverses', down[0] === String(Math.max(...data.rows.map(r => r.id))), down.slice(0, 3).join(','));
  await page.type('#case-filter', 'fail');
  const failing = data.rows.filter(r => !r.pass).length;
  const filtered = await rows();
  check('the filter keeps the matching cases', filtered.length === failing, `${filtered.length} shown, ${failing} failing`);
  const plots = await page.evaluate(() => document.querySelectorAll('#plots svg').length);
  check('one plot per collected quantity and varied parameter', plots === data.collect.length * data.params.length, `${plots} plots`);
  const limits = await page.evaluate(() => document.querySelectorAll('#plots line.limit').length);
  const limited = data.collect.filter(c => data.limits.some(l => l.collect === c)).length * data.params.length;
  check('a limit line where a quantity has a limit', limits === limited, `${limits} lines, ${limited} expected`);
  const map = await page.evaluate(() => ({ pass: document.querySelectorAll('#operability circle.pass').length, fail: document.querySelectorAll('#operability circle.fail').length }));
  const ran = data.rows.filter(r => r.status !== 'missing');
  check('the operability map has a point per case, green where it passes', map.pass === ran.filter(r => r.pass).length && map.pass + map.fail === ran.length, JSON.stringify(map));
}

// (report.html) => plots, replay, slider, cursor and timeline as a person uses them
async function checkReport(page) {

  const drawn = await drawnPixels(page);
  const groups = await page.evaluate(() => window.yardsim.plots.map(u => ({
    ...u.group, title: u.root.querySelector('.u-title') && u.root.querySelector('.u-title').textContent,
    ylabel: u.axes[1].label,  // uPlot draws it on the canvas
    ticks: u.axes[1]._values || [], max: Math.max(...u.data.slice(1).flatMap(d => [...d].filter(Number.isFinite).map(Math.abs))),
  })));
  check('one plot per quantity group, each with drawn pixels', drawn.length === groups.length && drawn.length > 0 && drawn.every(n => n > 500),
    `${drawn.length} canvases for ${groups.length} groups, pixels drawn ${drawn.join(', ')}`);
  const plotted = groups.flatMap(g => g.channels);
  check('every plotted channel in one plot', plotted.length === data.plots.length && data.plots.every(i => plotted.includes(data.series[i].name)),
    `${plotted.length} in plots, ${data.plots.length} plotted`);
  check('every plot has a title and its unit in the axis label', groups.every(g => g.title && g.ylabel && g.ylabel.endsWith(`[${g.unit}]`)),
    groups.map(g => `${g.title}: ${g.ylabel}`).join('; '));
  // (forces, masses, energies) => an engineering unit that keeps the numbers between 1 and 1000
  const ladder = { N: ['N', 'kN', 'MN'], kg: ['kg', 't'], J: ['J', 'kJ', 'MJ'], W: ['W', 'kW', 'MW'] };
  // (every recorded channel of a plot's group, plotted or not: the header's table and the plots
  // share its unit) => the group's largest magnitude in the unit shown
  const recordedGroups = groupSeries(data.series.map(x => {
    const b = Buffer.from(x.data || '', 'base64');
    return { ...x, values: new Float32Array(b.buffer, b.byteOffset, Math.floor(b.byteLength / 4)) };
  }));
  const recordedMax = g => {
    const r = recordedGroups.find(x => x.title === g.title && x.si === g.si);
    return r ? Math.max(g.max, ...r.list.map(x => maxAbs(x.values) * g.factor)) : g.max;
  };
  const scaled = groups.filter(g => ladder[g.si]).map(g => ({ ...g, max: recordedMax(g) }));
  check('forces in kN or MN (masses in t, ...) chosen by magnitude', scaled.every(g => ladder[g.si].includes(g.unit) &&
    (g.max < 1000 || g.unit === ladder[g.si].at(-1)) && (g.max >= 1 || g.unit === g.si || g.max === 0)),
  scaled.map(g => `${g.title} [${g.unit}] max ${g.max.toPrecision(3)}`).join('; '));
  check('angles in degrees', groups.filter(g => g.si === 'rad').every(g => g.unit === 'deg'));
  const tensions = groups.find(g => g.title === 'Rope tensions');
  if (tensions) {
    const head = await page.$eval('#peaks tr th:nth-child(2)', th => th.textContent).catch(() => '');
    check('the header table and the tension plot say the same unit', head.includes(`[${tensions.unit}]`), `${head} / ${tensions.unit}`);
  }
  const noise = await page.evaluate(() => document.body.innerText.match(/\d(\.\d+)?e-(1\d|[2-9]\d)/g));
  const tickNoise = groups.flatMap(g => g.ticks).filter(v => /e-(1\d|[2-9]\d)/.test(String(v)));
  check('no round-off noise (e-10 and below) in the text or the tick labels', !noise && !tickNoise.length, `${noise} ${tickNoise}`);

  // (run.json's alarms and warnings) => a red banner with a line per alarm and per warning, and
  // markers, exactly when there are any
  const alarms = ((data.run && data.run.alarms) || []).filter(a => a.severity === 'alarm' || a.severity === 'warning');
  const banner = await page.evaluate(() => {
    const b = document.getElementById('alarm-banner');
    return b && { items: [...b.querySelectorAll('li')].map(li => li.textContent), color: getComputedStyle(b).borderColor };
  });
  if (alarms.length) {
    check('a red banner lists every alarm and warning', banner && banner.items.length === alarms.length && /207, 34, 46/.test(banner.color),
      JSON.stringify(banner));
    const force = tensions ? tensions.unit : 'kN';
    const factor = { N: 1, kN: 1e-3, MN: 1e-6 }[force];
    for (const a of alarms.filter(x => x.kind === 'over_mbl')) {
      const rope = data.run.ropes.find(r => r.name === a.element || r.name.endsWith(`.${a.element}`));
      const shown = banner.items.find(t => t.includes(a.element) && t.startsWith('over_mbl'));
      const value = shown && Number(shown.match(/worst ([-0-9.e]+) /)[1]);
      check(`the banner gives ${a.element}'s peak tension (not its MBL) in ${force}`, rope && value &&
        Math.abs(value - rope.peak * factor) < 1e-3 * rope.peak * factor && rope.peak > rope.mbl && shown.includes(` ${force}`), shown);
    }
    const withUnit = alarms.filter(a => a.unit);
    check('every alarm\'s worst value with its unit', withUnit.every(a => {
      const shown = banner.items.find(t => t.startsWith(a.kind) && t.includes(` ${a.element} `));
      return shown && /worst -?[0-9.]+(e-?[0-9]+)? (mm|m|N|kN|MN|deg|t|kg)( at t = [0-9.]+ s)?$/.test(shown);
    }), banner.items.join(' | '));
    const warnings = alarms.filter(a => a.severity === 'warning');
    if (warnings.length)
      check('every warning in the banner with its text and count', warnings.every(a =>
        banner.items.some(t => t.startsWith('warning') && t.includes(a.message) && t.includes(`${a.count} time`))), banner.items.join(' | '));
    const markers = await page.evaluate(() => ({ n: window.yardsim.markers.length, tl: document.querySelectorAll('.tl-marker').length }));
    check('alarm markers on the plots and the timeline', markers.n >= alarms.length && markers.tl === markers.n, JSON.stringify(markers));
    // (markers) => one that is on top at its own centre (markers close in time overlap)
    await (await page.$('.tl-marker')).scrollIntoView();
    const marks = await page.$$('.tl-marker');
    let mark = marks[0];
    for (const m of marks)
      if (await m.evaluate(e => { const r = e.getBoundingClientRect(); return document.elementFromPoint(r.left + r.width / 2, r.top + r.height / 2) === e; })) { mark = m; break; }
    const target = await mark.evaluate(e => Number(e.dataset.t));
    await mark.click();
    const now = await page.evaluate(() => window.yardsim.time());
    check('a click on a marker moves the time there', Math.abs(now - target) < 1e-9 * Math.max(1, target), `${now} vs ${target}`);
  } else {
    check('no banner for a run without alarms', banner === null);
  }

  // (closest approaches) => a row per clearance watch
  const watches = data.series.filter(x => x.unit === 'm' && /\.distance$/.test(x.name));
  const closest = await page.$$eval('#closest tr', r => Math.max(0, r.length - 1));
  check('a closest-approach row per clearance watch', closest === watches.length, `${closest} rows, ${watches.length} watches`);

  // (three.js scene) => one mesh per body of replay.glb
  const meshes = await page.evaluate(() => {
    const r = window.yardsim.replay;
    if (!r) return null;
    const out = [];
    r.scene.traverse(o => { if (o.isMesh && o.userData.body !== undefined) out.push(o.userData.body); });
    return out;
  });
  if (required.length)
    check(`the replay shows ${required.join(', ')}, each moving`, meshes !== null &&
      required.every(n => meshes.includes(n) && bodies.some(b => b.name === n && b.travel > 0)),
    required.map(n => `${n}: ${(bodies.find(b => b.name === n) || { travel: 'absent' }).travel}`).join(', '));
  if (bodies.length)
    check('one mesh per body', meshes !== null && meshes.length === bodies.length &&
      bodies.every(b => meshes.includes(b.name)), `${meshes && meshes.length} meshes, ${bodies.length} bodies`);
  else
    check('no bodies, no replay', meshes === null && data.glb === null);

  // (a sea in run.json) => the water plane at its level, translucent; none on land
  const level = ((data.run && data.run.systems) || []).map(x => x.water_level).find(x => x !== undefined);
  const water = await page.evaluate(() => {
    const w = window.yardsim.replay && window.yardsim.replay.scene.getObjectByName('water');
    return w && { y: w.getWorldPosition(w.position.clone()).y, opacity: w.material.opacity, transparent: w.material.transparent };
  });
  if (level !== undefined) check('a translucent water plane at the water level', water && Math.abs(water.y - level) < 1e-6 && water.transparent && water.opacity < 1, JSON.stringify(water));
  else check('no water plane on land', !water);
  // (contact force channels) => an arrow per body with a force, shown where the force is
  const sets = data.series.filter(x => /\.normal_force$/.test(x.name)).map(x => x.name.replace(/normal_force$/, ''));
  const contacts = data.series.filter(x => x.unit === 'N' && /\.fz$/.test(x.name) && sets.some(p => x.name.startsWith(p)));
  if (contacts.length) {
    const arrows = await page.evaluate(() => {
      const y = window.yardsim;
      y.setTime(y.data.run.t_end, 'test');
      return y.replay.arrows.list.map(a => ({ channel: a.channel, visible: a.arrow.visible, force: a.force, max: a.max }));
    });
    check('contact forces drawn as arrows at the end of the run', arrows.length > 0 && arrows.every(a => a.visible === Math.abs(a.force) > 1e-3 * a.max) && arrows.some(a => a.visible),
      JSON.stringify(arrows));
    // (point of application channels <set>.<body>.px|py|pz) => a dot at the last recorded point,
    // z-up world (x, y, z) drawn at three.js's y-up (x, z, -y)
    const last = name => {  // (channel) => its last sample (float32, as the page has it)
      const x = data.series.find(s => s.name === name);
      if (!x) return undefined;
      const v = new Float32Array(Uint8Array.from(Buffer.from(x.data, 'base64')).buffer);
      return v[v.length - 1];
    };
    const expected = contacts.map(c => ({ channel: c.name, p: ['px', 'py', 'pz'].map(k => last(c.name.replace(/fz$/, k))) }))
      .filter(e => e.p.every(v => v !== undefined));
    if (expected.length) {
      const dots = await page.evaluate(() => window.yardsim.replay.arrows.list.map(a => ({ channel: a.channel, visible: a.dot.visible, p: [a.dot.position.x, a.dot.position.y, a.dot.position.z] })));
      const ok = expected.every(e => {
        const d = dots.find(x => x.channel === e.channel);
        if (!e.p.every(Number.isFinite)) return d ? !d.visible : true;
        const want = [e.p[0], e.p[2], -e.p[1]];
        return d && d.visible && want.every((w, i) => Math.abs(d.p[i] - w) < 1e-6 * (1 + Math.abs(w)));
      });
      check('contact points drawn where the forces act at the end of the run', ok && expected.some(e => e.p.every(Number.isFinite)), JSON.stringify({ expected, dots }));
    }
    await page.evaluate(() => window.yardsim.setTime(0, 'test'));
  }

  // (slider clicked at 3/4) => the time, the most-travelled body and the plot cursors follow
  // the block (a body named block) when there is one, else the body that travels most
  const block = bodies.find(b => /(^|\.)block$/.test(b.name)) || bodies.reduce((a, b) => (b.travel > a.travel ? b : a), bodies[0] || null);
  const probe = () => page.evaluate(name => {
    const y = window.yardsim;
    const b = name && y.replay.bodies.find(o => o.userData.body === name);
    const p = b ? b.getWorldPosition(b.position.clone()) : { x: 0, y: 0, z: 0 };
    return { t: y.time(), slider: Number(document.getElementById('time-slider').value), p: [p.x, p.y, p.z], cursor: y.plots.map(u => u.cursor.left) };
  }, block && block.name);
  const before = await probe();
  const slider = await page.$('#time-slider');
  await slider.scrollIntoView();
  const box = await slider.boundingBox();
  await page.mouse.click(box.x + 0.75 * box.width, box.y + box.height / 2);
  const after = await probe();
  check('the slider moves the time', after.t > before.t && after.slider > 0, `t ${before.t} -> ${after.t}`);
  if (block) {
    const moved = Math.hypot(...after.p.map((x, i) => x - before.p[i]));
    check(`the slider moves ${block.name}`, block.travel > 0 && moved > 1e-3 * block.travel, `moved ${moved.toFixed(4)} (travel ${block.travel.toFixed(3)})`);
  }
  const expected = await page.evaluate(t => window.yardsim.plots.map(u => u.valToPos(t, 'x')), after.t);
  check('the slider moves the plot cursor', after.cursor.length > 0 &&
    after.cursor.every((l, i) => Math.abs(l - expected[i]) < 1.5 && l !== before.cursor[i]), `${before.cursor} -> ${after.cursor}`);

  // (mouse over the first plot at 1/4) => the slider and the time follow
  const over = await page.evaluate(() => {
    const u = window.yardsim.plots[0];
    u.over.scrollIntoView({ block: 'center' });
    const r = u.over.getBoundingClientRect();
    return { x: r.left + 0.25 * r.width, y: r.top + r.height / 2, t: u.posToVal(0.25 * r.width, 'x') };
  });
  await page.mouse.move(over.x - 5, over.y, { steps: 2 });
  await page.mouse.move(over.x, over.y, { steps: 2 });
  await new Promise(r => setTimeout(r, 100));
  const hovered = await probe();
  check('the plot cursor moves the slider', Math.abs(hovered.slider - over.t) < 0.02 * Math.max(after.t, 1) && hovered.slider < after.slider,
    `slider ${hovered.slider}, cursor at t = ${over.t}`);

  // (timeline) => one row per actor
  const rows = await page.$$eval('.tl-row:not(.tl-alarm-row)', r => r.length);
  check('one timeline row per actor', rows === actors.size, `${rows} rows, ${actors.size} actors`);
  const bars = await page.$$eval('.tl-bar', r => r.length);
  check('a bar for every actor that started', bars === [...actors].filter(a => data.actors.find(x => x.path === a && x.start >= 0)).length, `${bars} bars`);

  await page.mouse.move(0, 0);
  await page.evaluate(() => window.yardsim.setTime(window.yardsim.data.run ? window.yardsim.data.run.t_end * 0.5 : 0, 'test'));
}
