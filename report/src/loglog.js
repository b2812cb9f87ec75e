// A page of log-log plots (wp.html): per plot, one curve per label through its points sorted by
// x, both axes logarithmic; points with a coordinate <= 0 or not finite are left out and counted.
import uPlot from 'uplot';
import { el, float32, fmt } from './data.js';
import { palette } from './plots.js';

// (ticks) => labels on the powers of ten only
const decades = (u, ticks) => ticks.map(v => (v > 0 && Math.abs(Math.log10(v) - Math.round(Math.log10(v))) < 1e-6 ? fmt(v, 2) : ''));

export function renderLogLog(data, root) {
  root.append(el('h1', {}, data.title));
  const facts = el('table', { class: 'run-facts' });
  for (const [k, v] of data.facts) facts.append(el('tr', {}, el('th', {}, k), el('td', {}, v)));
  root.append(facts);
  for (const n of data.notes) root.append(el('p', { class: 'notes' }, n));
  const box = el('div', { class: 'plots', id: 'plots' });
  root.append(box);
  const plots = [];
  for (const p of data.plots) {
    let dropped = 0;
    const tables = p.curves.map(c => {
      const xs = float32(c.xs), ys = float32(c.ys), pts = [];
      for (let i = 0; i < xs.length; i++) {
        if (xs[i] > 0 && ys[i] > 0 && Number.isFinite(xs[i]) && Number.isFinite(ys[i])) pts.push([xs[i], ys[i]]);
        else dropped++;
      }
      pts.sort((a, b) => a[0] - b[0]);
      return [Float64Array.from(pts, q => q[0]), Float64Array.from(pts, q => q[1])];
    });
    const joined = tables.length ? uPlot.join(tables) : [[]];
    const div = el('div', { class: 'plot' }, el('h3', {}, p.title));
    box.append(div);
    if (dropped) div.append(el('p', { class: 'notes' }, `${dropped} point(s) with a value <= 0 not drawn on log axes`));
    plots.push(new uPlot({
      width: 620, height: 380,
      scales: { x: { time: false, distr: 3 }, y: { distr: 3 } },
      axes: [{ label: p.x, values: decades }, { label: p.y, size: 72, values: decades }],
      series: [{ label: p.x, value: (u, v) => fmt(v, 4) },
        ...p.curves.map((c, i) => ({ label: c.label, stroke: palette[i % palette.length], width: 1.5, spanGaps: true,
          points: { show: true, size: 7 }, value: (u, v) => fmt(v, 4) }))],
    }, joined, div));
  }
  return plots;
}
