// The run's safety events on the page (run.json "alarms", the trace's events): a red banner in
// the header with one line per alarm (kind, element, first time, count, worst value in the
// page's units and when; a click seeks the replay there) and per warning the run printed (the
// stiffness guard's: its text, count and omega_max dt), the notices in a quiet line below, the times of
// every occurrence as markers for the plots and the timeline, and the table of the closest
// approaches of the clearance watches.
import { el } from './data.js';
import { displayUnit, maxAbs, num } from './units.js';

const what = {
  over_mbl: 'over its minimum breaking load',
  over_hook_load: 'over its hook-load curve',
  crossed: 'past its threshold',
  clearance_below: 'clearance below its limit',
  touched: 'touched',
  slack: 'slack', taut: 'taut', contact: 'contact', release: 'release',
};

// (alarm) => whether it goes into the banner: an alarm or a warning (not a notice)
const banned = a => a.severity === 'alarm' || a.severity === 'warning';

// (alarm, the force unit of the page) => its worst value with a unit: forces in the page's force
// unit (the tension plot's), the rest in the display unit of run.json's SI unit for it
function worst(a, force) {
  const si = a.unit !== undefined ?
      a.unit :
      (a.kind === 'over_mbl' || a.kind === 'over_hook_load' ? 'N' : '');
  if (si === 'N') return `${num(a.worst * force.factor)} ${force.unit}`;
  if (a.kind === 'contact' || a.kind === 'release') return `${num(a.worst * 1e3)} mm deep`;
  if (!si) return num(a.worst);
  const d = displayUnit(si, Math.abs(a.worst));
  return `${num(a.worst * d.factor)} ${d.unit}`;
}

// (alarms, events) => per alarm the times of its occurrences: its first, and every event of its
// model, element and kind in the trace
export function alarmTimes(alarms, events) {
  return alarms.map(a => {
    const ts = new Set([a.first]);
    for (const e of events) if (e.model === a.model && e.element === a.element && e.what === a.kind) ts.add(e.t);
    return [...ts].sort((x, y) => x - y);
  });
}

// (alarms, events) => plot and timeline markers [{t, color, label, severity}]
export function alarmMarkers(alarms, events) {
  const times = alarmTimes(alarms, events);
  const out = [];
  alarms.forEach((a, i) => {
    for (const t of times[i])
      out.push({ t, severity: a.severity, color: { alarm: '#cf222e', warning: '#9a6700' }[a.severity] || '#8c959f', label: `${a.element} ${a.kind}` });
  });
  return out.filter(banned);
}

// (alarms, force display unit, root, onTime) => the banner (only when there is an alarm) and the
// notices line
export function alarmBanner(alarms, force, root, onTime) {
  const times = a => `${a.count} time${a.count === 1 ? '' : 's'}`;
  const when = a => (a.worst_at !== undefined && a.worst_at !== null ? ` at t = ${num(a.worst_at, 6)} s` : '');
  const line = a => {
    const text = a.severity === 'warning' ?
        ` ${a.element}: ${a.message}: from t = ${num(a.first, 6)} s, ${times(a)}${a.worst === null ? '' : `, value ${num(a.worst)}`}` :
        ` ${a.element} ${what[a.kind] || ''}: first at t = ${num(a.first, 6)} s, ${times(a)}, worst ${worst(a, force)}${when(a)}`;
    const item = el('li', { class: 'alarm-item', 'data-kind': a.kind }, el('b', {}, a.kind), text);
    item.title = 'click: show this time';
    item.addEventListener('click', () => onTime(a.first, 'alarm'));
    return item;
  };
  const bad = alarms.filter(banned);
  if (bad.length) {
    const count = (n, w) => `${n} ${w}${n === 1 ? '' : 's'}`;
    const nA = bad.filter(a => a.severity === 'alarm').length, nW = bad.length - nA;
    const title = [nA ? count(nA, 'alarm') : '', nW ? count(nW, 'warning') : ''].filter(Boolean).join(' and ');
    root.append(el('div', { class: 'alarm-banner', id: 'alarm-banner' },
      el('div', { class: 'alarm-title' }, `${title} in this run`),
      el('ul', {}, ...bad.map(line))));
  }
  const notices = alarms.filter(a => !banned(a));
  if (notices.length) {
    const list = el('ul', {}, ...notices.map(line));
    root.append(el('details', { class: 'notices-list', id: 'notices' }, el('summary', {}, `${notices.length} notice${notices.length === 1 ? '' : 's'} (slack/taut ropes, contacts)`), list));
  }
}

// (every recorded series, time, events, container, onTime) => the table of the clearance
// watches' closest approaches: minimum distance, when, between what (from the watch's last
// clearance_below/touched event at or before it), or nothing when the scene has no watch
export function closestApproaches(series, time, events, container, onTime) {
  const watches = series.filter(s => s.unit === 'm' && /\.distance$/.test(s.name));
  if (!watches.length) return [];
  const rows = watches.map(s => {
    let k = -1;
    for (let i = 0; i < s.values.length; i++) if (Number.isFinite(s.values[i]) && (k < 0 || s.values[i] < s.values[k])) k = i;
    const watch = s.name.replace(/\.distance$/, '');
    const near = events.filter(e => e.element === watch && (e.what === 'clearance_below' || e.what === 'touched'));
    const pair = near.length ? near[near.length - 1].detail : '';
    return { watch, min: k >= 0 ? s.values[k] : NaN, t: k >= 0 ? time[k] : NaN, pair, events: near.length };
  });
  const d = displayUnit('m', maxAbs(rows.map(r => r.min)));
  const table = el('table', { class: 'closest', id: 'closest' },
    el('tr', {}, el('th', {}, 'clearance watch'), el('th', {}, `minimum distance [${d.unit}]`), el('th', {}, 'at [s]'),
      el('th', {}, 'pair and witness points (last event)'), el('th', {}, 'events')));
  for (const r of rows) {
    const tr = el('tr', {}, el('td', {}, r.watch), el('td', { class: 'num' }, num(r.min * d.factor)), el('td', { class: 'num' }, num(r.t, 6)),
      el('td', {}, r.pair || '– (no clearance_below or touched event)'), el('td', { class: 'num' }, String(r.events)));
    tr.addEventListener('click', () => onTime(r.t, 'closest'));
    table.append(tr);
  }
  container.append(el('h2', {}, 'Closest approaches'), table,
    el('p', { class: 'hint' }, 'Sampled on the record grid; a watch reports the range (its `range`, by default `below`) when nothing is nearer.'));
  return rows;
}
