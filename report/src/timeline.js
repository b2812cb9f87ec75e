// The actor timeline: one row per actor, a bar from `started` to `finished` coloured by kind, and
// a row of the alarms' markers (alarms.js) when there are any; clicking a row or a marker sets
// the report's time.
import { el, fmt } from './data.js';

const kindColors = ['#0969da', '#bf8700', '#1a7f37', '#8250df', '#cf222e', '#1b7c83'];

// (actors [{path, kind, start, end}], end time, container, onTime, markers [{t, color, label}])
// => {setTime(t)}
export function makeTimeline(actors, tEnd, container, onTime, markers = []) {
  if (!actors.length) container.append(el('p', { class: 'notes' }, 'no actors in this scene'));
  const kinds = [...new Set(actors.map(a => a.kind))];
  const color = k => kindColors[kinds.indexOf(k) % kindColors.length];
  const legend = el('div', { class: 'tl-legend' });
  for (const k of kinds) legend.append(el('span', { class: 'legend-kind', style: `background:${color(k)}` }), k);
  container.append(legend);
  const box = el('div', { class: 'timeline' });
  container.append(box);
  const span = tEnd > 0 ? tEnd : 1;
  const pct = t => `${(100 * Math.min(Math.max(t, 0), span)) / span}%`;
  const cursors = [];
  for (const a of actors) {
    const track = el('div', { class: 'tl-track' });
    if (a.start >= 0) {
      const end = a.end >= 0 ? a.end : span;
      const bar = el('div', { class: 'tl-bar', style: `left:${pct(a.start)};width:calc(${pct(end)} - ${pct(a.start)} + 2px);background:${color(a.kind)}` });
      bar.title = `${a.path} (${a.kind}): ${fmt(a.start)} s – ${a.end >= 0 ? fmt(a.end) + ' s' : 'not finished'}`;
      track.append(bar);
    }
    const cursor = el('div', { class: 'tl-cursor' });
    cursors.push(cursor);
    track.append(cursor);
    track.addEventListener('click', e => {
      const r = track.getBoundingClientRect();
      onTime(((e.clientX - r.left) / r.width) * span, 'timeline');
    });
    box.append(el('div', { class: 'tl-row' }, el('div', { class: 'tl-label', title: a.path }, a.path), track));
  }
  // (alarms) => one row of markers, each a click to its time
  if (markers.length) {
    const track = el('div', { class: 'tl-track tl-alarms' });
    for (const m of markers) {
      const mark = el('div', { class: 'tl-marker', 'data-t': String(m.t), style: `left:${pct(m.t)};background:${m.color}` });
      mark.title = `${m.label} at ${fmt(m.t, 6)} s`;
      mark.addEventListener('click', e => { e.stopPropagation(); onTime(m.t, 'alarm'); });
      track.append(mark);
    }
    const cursor = el('div', { class: 'tl-cursor' });
    cursors.push(cursor);
    track.append(cursor);
    box.append(el('div', { class: 'tl-row tl-alarm-row' }, el('div', { class: 'tl-label alarm-label' }, 'alarms'), track));
  }
  container.append(el('div', { class: 'tl-axis' }, el('span', {}, '0 s'), el('span', {}, `${fmt(span / 2)} s`), el('span', {}, `${fmt(span)} s`)));
  return { setTime(t) { for (const c of cursors) c.style.left = pct(t); } };
}
