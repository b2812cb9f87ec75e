// Time-series plots (uPlot): one chart per quantity group (rope tensions, heights, heel and trim,
// ...; units.js) with its title and its engineering unit in the axis label, a shared time
// cursor, drag-to-zoom shared across charts (double-click resets), the scene's static levels as
// dashed lines labelled in the right margin beside the curve, and the alarms as red vertical
// markers.
import uPlot from 'uplot';
import { el } from './data.js';
import { cleaned, groupSeries, num, tickLabels } from './units.js';

export const palette = ['#1f77b4', '#d62728', '#2ca02c', '#ff7f0e', '#9467bd', '#8c564b', '#e377c2', '#17becf', '#7f7f7f', '#bcbd22'];

const gutter = 132;  // px right of the plot area for the static levels' labels

// (labels [{y, ...}] in canvas px, line height) => the same, moved apart vertically so that none
// overlaps the next, in their order
function spread(labels, h) {
  labels.sort((a, b) => a.y - b.y);
  for (let i = 1; i < labels.length; i++) labels[i].y = Math.max(labels[i].y, labels[i - 1].y + h);
  return labels;
}

// (series [{name, unit, values}], every recorded series, time, static {name: SI value}, markers
// [{t, color, label}], container, onTime(t)) => {plots, groups, setTime(t)}
export function makePlots(series, recorded, time, staticLevels, markers, container, onTime) {
  const groups = groupSeries(series, recorded);
  const plots = [];
  let quiet = false;  // set while this module moves cursors or scales itself
  const width = () => Math.max(380, Math.min(container.clientWidth - 8, 1400) / (groups.length > 1 ? 2 : 1) - 24);
  for (const g of groups) {
    const { list, factor, unit } = g;
    const levels = list.filter(s => staticLevels[s.name] !== undefined)
      .map(s => ({ value: staticLevels[s.name] * factor, color: palette[list.indexOf(s) % palette.length], name: s.name }));
    const box = el('div', { class: 'plot' });
    container.append(box);
    const scaleOf = values => { let m = 0; for (const v of values) if (Number.isFinite(v)) m = Math.max(m, Math.abs(v)); return m; };
    const data = list.map(s => cleaned(s.values, factor, g.scale));
    const span = Math.max(...data.map(scaleOf), 0);
    const opts = {
      title: g.title,
      width: width(),
      height: 240,
      padding: [8, levels.length ? gutter : 12, 0, 0],
      cursor: { y: false, sync: { key: 'yardsim' }, drag: { x: true, y: false } },
      scales: {
        x: { time: false },
        y: {
          range: (u, lo, hi) => {
            for (const l of levels) { lo = Math.min(lo, l.value); hi = Math.max(hi, l.value); }
            if (lo === hi) { lo -= 1; hi += 1; }  // a constant (0 once cleaned): a visible band
            return uPlot.rangeNum(lo, hi, 0.1, true);
          },
        },
      },
      axes: [{ label: 'time [s]' }, { label: `${g.quantity} [${unit}]`, size: 72, values: (u, ticks) => tickLabels(ticks) }],
      series: [{ label: 'time [s]', value: (u, v) => num(v, 6) },
        ...list.map((s, i) => ({ label: s.name, stroke: palette[i % palette.length], width: 1.5, value: (u, v) => num(v, 5, span) }))],
      hooks: {
        draw: [u => {
          const { ctx } = u;
          const px = devicePixelRatio;
          ctx.save();
          // (alarms) => red vertical markers at their times
          ctx.lineWidth = 1.5 * px;
          for (const m of markers) {
            if (m.t < u.scales.x.min || m.t > u.scales.x.max) continue;
            const x = u.valToPos(m.t, 'x', true);
            ctx.strokeStyle = m.color;
            ctx.beginPath();
            ctx.moveTo(x, u.bbox.top);
            ctx.lineTo(x, u.bbox.top + u.bbox.height);
            ctx.stroke();
          }
          // (static levels) => dashed lines, one label per level in the right margin
          ctx.setLineDash([6, 4]);
          ctx.font = `${11 * px}px sans-serif`;
          ctx.textAlign = 'left';
          ctx.textBaseline = 'middle';
          const labelled = new Map();  // value => channels at that level (one label each)
          for (const l of levels) {
            const y = u.valToPos(l.value, 'y', true);
            ctx.strokeStyle = l.color;
            ctx.beginPath();
            ctx.moveTo(u.bbox.left, y);
            ctx.lineTo(u.bbox.left + u.bbox.width, y);
            ctx.stroke();
            if (!labelled.has(l.value)) labelled.set(l.value, []);
            labelled.get(l.value).push(l);
          }
          const labels = spread([...labelled].map(([value, ls]) => ({
            y: u.valToPos(value, 'y', true), color: ls[0].color,
            text: `static ${num(value, 4)}${ls.length > 1 ? ` (${ls.length})` : ''}`,
          })), 13 * px);
          for (const l of labels) {
            ctx.fillStyle = l.color;
            ctx.fillText(l.text, u.bbox.left + u.bbox.width + 6 * px, l.y);
          }
          ctx.restore();
        }],
        // (cursor moved by the user) => the report's time
        setCursor: [u => {
          if (quiet || u.cursor.idx === null || u.cursor.idx === undefined || u.cursor.left < 0) return;
          onTime(u.data[0][u.cursor.idx], 'plot');
        }],
        // (zoom on one chart) => the same time range on the others
        setScale: [(u, key) => {
          if (quiet || key !== 'x') return;
          quiet = true;
          for (const p of plots) if (p !== u) p.setScale('x', { min: u.scales.x.min, max: u.scales.x.max });
          quiet = false;
        }],
      },
    };
    const plot = new uPlot(opts, [time, ...data], box);
    plot.group = { title: g.title, unit, si: g.si, factor, channels: list.map(s => s.name), levels: levels.length };
    plots.push(plot);
  }
  window.addEventListener('resize', () => { for (const p of plots) p.setSize({ width: width(), height: 240 }); });
  return {
    plots,
    groups,
    // (t) => every chart's cursor at t
    setTime(t) {
      quiet = true;
      for (const p of plots) p.setCursor({ left: p.valToPos(t, 'x'), top: p.bbox.height / devicePixelRatio / 2 });
      quiet = false;
    },
  };
}
