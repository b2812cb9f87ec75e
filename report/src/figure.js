// One static chart of chosen channels, for figures in documents (report/figure.mjs sets
// window.yardsimFigure before the page loads): the channels whose names match the globs, times
// a scale, with a y label and an optional title; no cursor, legend with the names only.
import uPlot from 'uplot';
import { el, float32, fmt } from './data.js';
import { palette } from './plots.js';

// (glob with * ? [..]) => RegExp of the whole name
const globRe = g => new RegExp(`^${g.replace(/[.+^${}()|\\]/g, '\\$&').replace(/\*/g, '.*').replace(/\?/g, '.')}$`);

export function renderFigure(data, fig, root) {
  const res = (fig.channels || ['*']).map(globRe);
  const chosen = data.series.filter(s => res.some(r => r.test(s.name)));
  if (!chosen.length) throw new Error(`figure: no recorded channel matches ${fig.channels.join(', ')}`);
  const scale = fig.scale || 1;
  const box = el('div', { id: 'figure', style: 'display:inline-block;padding:8px;background:#fff' });
  if (fig.title) box.append(el('h3', { style: 'margin:0 0 4px;font-size:14px' }, fig.title));
  root.append(box);
  const time = float32(data.time);
  const values = chosen.map(s => Float64Array.from(float32(s.data), v => v * scale));
  const ylabel = fig.ylabel || `[${chosen[0].unit}]`;
  return new uPlot({
    width: fig.width || 760,
    height: fig.height || 360,
    cursor: { show: false },
    legend: { live: false },
    scales: { x: { time: false } },
    axes: [{ label: 'time [s]' }, { label: ylabel, size: 72, values: (u, t) => t.map(v => fmt(v, 3)) }],
    series: [{ label: 'time [s]' }, ...chosen.map((s, i) => ({ label: s.name, stroke: palette[i % palette.length], width: 2, points: { show: false } }))],
  }, [time, ...values], box);
}
