// yardsim's pages (report.html; wp.html, see loglog.js; sweep.html, see sweep.js): reads the data the yardsim binary put in the page and
// draws the header, the 3D replay, the actor timeline and the plots, all on one time shared
// both ways (slider and play, plot cursor, timeline). window.yardsim exposes the parts for the
// browser test (report/test/browser_test.mjs).
import uplotCss from 'uplot/dist/uPlot.min.css';
import css from './style.css';
import { bytes, el, float32, fmt, readData } from './data.js';
import { makePlots } from './plots.js';
import { alarmBanner, alarmMarkers, closestApproaches } from './alarms.js';
import { groupSeries, num } from './units.js';
import { makeTimeline } from './timeline.js';
import { makeReplay } from './replay3d.js';
import { renderLogLog } from './loglog.js';
import { renderFigure } from './figure.js';
import { renderSweep } from './sweep.js';

// (page data, end time, every recorded series, root, onTime) => the header: title, alarm banner,
// run facts, the ropes' peaks in the tensions' display unit (the one of their plot)
function header(data, tEnd, recorded, root, onTime) {
  const run = data.run || {};
  root.append(el('h1', {}, `yardsim report: ${run.scene || data.meta.scene || '(unknown scene)'}`));
  const systems = (run.systems || []).map(s => `${s.method}, dt = ${fmt(s.dt)} s (${s.model})`);
  if (!systems.length && run.integrator && run.integrator !== 'none') systems.push(`${run.integrator}, dt = ${fmt(run.step)} s`);
  const facts = el('table', { class: 'run-facts' });
  const row = (k, v, cls = '') => facts.append(el('tr', {}, el('th', {}, k), el('td', { class: cls }, v)));
  row('scene file', run.file || data.meta.scene || '–');
  row('integrator, step', systems.length ? systems.join('; ') : 'none (no multibody model)');
  row('simulated', `${fmt(run.t_end ?? tEnd)} s`);
  row('wall time', run.wall !== undefined ? `${fmt(run.wall, 3)} s` : '–');
  row('real-time factor', run.real_time_factor !== undefined ? `${fmt(run.real_time_factor, 3)} ×` : '–');
  if (run.status === 'failed') row('status', `failed: ${run.message}`, 'failed');
  row('yardsim', run.yardsim || data.meta.yardsim || '–');
  const tensions = groupSeries(recorded.filter(s => /\.(peak_)?tension$/.test(s.name) && s.unit === 'N'))[0] || { unit: 'kN', factor: 1e-3 };
  const force = { unit: tensions.unit, factor: tensions.factor };
  const peaks = el('table', { class: 'peaks', id: 'peaks' },
    el('tr', {}, el('th', {}, 'rope'), el('th', {}, `peak tension [${force.unit}]`), el('th', {}, 'at [s]'),
      el('th', {}, `static [${force.unit}]`), el('th', {}, 'peak / static')));
  for (const p of data.peaks) {
    peaks.append(el('tr', {}, el('td', {}, p.channel.replace(/\.tension$/, '')),
      el('td', { class: 'num' }, num(p.peak * force.factor)), el('td', { class: 'num' }, fmt(p.time)),
      el('td', { class: 'num' }, p.static === null ? '–' : num(p.static * force.factor)),
      el('td', { class: 'num' }, p.static ? fmt(p.peak / p.static, 3) : '–')));
  }
  alarmBanner(run.alarms || [], force, root, onTime);
  root.append(el('div', { class: 'facts' }, facts, data.peaks.length ? peaks : el('div', {}, 'no rope tension recorded')));
  for (const n of data.notes) root.append(el('p', { class: 'notes' }, n));
}

async function main() {
  for (const text of [uplotCss, css]) document.head.append(el('style', {}, text));
  const data = readData();
  if (window.yardsimFigure) {
    document.body.style.background = '#fff';
    window.yardsim = { data, plots: [renderFigure(data, window.yardsimFigure, document.body)], ready: true };
    return;
  }
  if (data.kind === 'sweep') {
    const root = el('div', { id: 'report' });
    document.body.append(root);
    window.yardsim = { data, table: renderSweep(data, root), ready: true };
    return;
  }
  if (data.kind === 'loglog') {
    const root = el('div', { id: 'report' });
    document.body.append(root);
    window.yardsim = { data, plots: renderLogLog(data, root), ready: true };
    return;
  }
  const time = float32(data.time);
  const tEnd = time.length ? time[time.length - 1] : 0;
  const root = el('div', { id: 'report' });
  document.body.append(root);
  const recorded = data.series.map(s => ({ ...s, values: float32(s.data) }));
  const events = data.events || [];
  let setTime = () => {};
  header(data, tEnd, recorded, root, (t, from) => setTime(t, from));

  // (controls) => slider, play/pause, speed
  const slider = el('input', { type: 'range', id: 'time-slider', min: '0', max: String(tEnd), step: String(tEnd / 2000 || 1), value: '0' });
  const play = el('button', { id: 'play' }, 'play');
  const speed = el('select', { id: 'speed' });
  const base = Math.max(1, Math.round(tEnd / 20));
  for (const s of [1, base, base * 4].filter((x, i, a) => a.indexOf(x) === i)) speed.append(el('option', { value: String(s) }, `${s}×`));
  speed.value = String(base);
  const label = el('span', { class: 'time' }, 't = 0 s');
  const replayBox = el('div', { class: 'replay-view', id: 'replay' });
  root.append(el('h2', {}, '3D replay'), replayBox, el('div', { class: 'controls' }, play, speed, slider, label));
  const timelineBox = el('div', { id: 'timeline' });
  root.append(el('h2', {}, 'Actors'), timelineBox);
  const closestBox = el('div', { id: 'closest-approaches' });
  root.append(closestBox);
  const plotBox = el('div', { class: 'plots', id: 'plots' });
  root.append(el('h2', {}, 'Time series'), plotBox);

  const series = data.plots.map(i => recorded[i]);
  const markers = alarmMarkers((data.run && data.run.alarms) || [], events);
  let now = 0;
  let replay = null;
  const views = {};
  // (t, who moved it) => every view at t except the one that moved it
  setTime = (t, from) => {
    now = Math.min(Math.max(t, 0), tEnd);
    if (from !== 'slider') slider.value = String(now);
    label.textContent = `t = ${fmt(now, 5)} s`;
    if (replay) replay.setTime(now);
    if (from !== 'plot') views.plots.setTime(now);
    views.timeline.setTime(now);
  };
  views.plots = makePlots(series, recorded, time, data.static, markers, plotBox, setTime);
  views.timeline = makeTimeline(data.actors, tEnd, timelineBox, setTime, markers);
  const closest = closestApproaches(recorded, time, events, closestBox, setTime);
  slider.addEventListener('input', () => setTime(Number(slider.value), 'slider'));
  let playing = false, last = 0;
  function frame(ts) {
    if (!playing) return;
    const dt = last ? (ts - last) / 1000 : 0;
    last = ts;
    setTime(now + dt * Number(speed.value), 'play');
    if (now >= tEnd) { playing = false; play.textContent = 'play'; return; }
    requestAnimationFrame(frame);
  }
  play.addEventListener('click', () => {
    playing = !playing;
    play.textContent = playing ? 'pause' : 'play';
    if (playing) { if (now >= tEnd) setTime(0, 'play'); last = 0; requestAnimationFrame(frame); }
  });
  // (run.json's systems, the contact channels) => the replay's water surface and contact forces
  const levels = ((data.run && data.run.systems) || []).map(x => x.water_level).filter(x => x !== undefined);
  // (collision sets: a `<set>.normal_force` channel) => their `<set>.<body>.fz` channels
  const sets = recorded.filter(s => /\.normal_force$/.test(s.name)).map(s => s.name.replace(/normal_force$/, ''));
  // (each body's fz) => with its point of application `<set>.<body>.px|py|pz` when recorded
  const contacts = recorded.filter(s => s.unit === 'N' && /\.fz$/.test(s.name) && sets.some(p => s.name.startsWith(p)))
    .map(s => {
      const point = ['px', 'py', 'pz'].map(k => recorded.find(r => r.name === s.name.replace(/fz$/, k)));
      return { name: s.name, values: s.values, point: point.every(Boolean) ? point.map(r => r.values) : null };
    });
  if (data.glb) replay = await makeReplay(bytes(data.glb), replayBox, { water: levels.length ? levels[0] : null, contacts, time });
  else {
    replayBox.className = '';
    replayBox.append(el('p', { class: 'notes' }, 'no replay.glb: the scene has no bodies, or records nothing'));
  }
  setTime(0, 'init');
  window.yardsim = { data, plots: views.plots.plots, groups: views.plots.groups, markers, closest, replay, setTime, time: () => now, ready: true };
}

window.yardsim = { ready: false };
main().catch(e => { window.yardsim.error = String(e && e.stack || e); console.error(e); });
