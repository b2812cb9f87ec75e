// Time-series plots (uPlot): the plotted channels grouped by unit, one chart per unit, with a
// shared time cursor, drag-to-zoom shared across charts (double-click resets), and the scene's
// static levels as dashed lines.
import uPlot from 'uplot';
import { el, fmt } from './data.js';

export const palette = ['#1f77b4', '#d62728', '#2ca02c', '#ff7f0e', '#9467bd', '#8c564b', '#e377c2', '#17becf', '#7f7f7f', '#bcbd22'];

// (series [{name, unit, values}], time, static {name: value}, container, onTime(t)) => {plots, setTime(t)}
export function makePlots(series, time, staticLevels, container, onTime) {
  const groups = new Map();
  for (const s of series) {
    if (!groups.has(s.unit)) groups.set(s.unit, []);
    groups.get(s.unit).push(s);
  }
  const plots = [];
  let quiet = false;  // set while this module moves cursors or scales itself
  const width = () => Math.max(360, Math.min(container.clientWidth - 8, 1400) / (groups.size > 1 ? 2 : 1) - 24);
  for (const [unit, list] of groups) {
    const levels = list.filter(s => staticLevels[s.name] !== undefined)
      .map(s => ({ value: staticLevels[s.name], color: palette[list.indexOf(s) % palette.length], name: s.name }));
    const box = el('div', { class: 'plot' }, el('h3', {}, `[${unit}]`));
    container.append(box);
    const opts = {
      width: width(),
      height: 240,
      cursor: { y: false, sync: { key: 'yardsim' }, drag: { x: true, y: false } },
      scales: {
        x: { time: false },
        y: {
          range: (u, lo, hi) => {
            for (const l of levels) { lo = Math.min(lo, l.value); hi = Math.max(hi, l.value); }
            return uPlot.rangeNum(lo, hi, 0.1, true);
          },
        },
      },
      axes: [{ label: 'time [s]' }, { label: `[${unit}]`, size: 72, values: (u, ticks) => ticks.map(v => fmt(v, 3)) }],
      series: [{ label: 'time [s]', value: (u, v) => fmt(v, 5) },
        ...list.map((s, i) => ({ label: s.name, stroke: palette[i % palette.length], width: 1.5, value: (u, v) => fmt(v, 5) }))],
      hooks: {
        // (static levels) => dashed lines with their names
        draw: [u => {
          const { ctx } = u;
          ctx.save();
          ctx.setLineDash([6, 4]);
          ctx.lineWidth = 1.5 * devicePixelRatio;
          ctx.font = `${11 * devicePixelRatio}px sans-serif`;
          ctx.textAlign = 'left';
          ctx.textBaseline = 'bottom';
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
          for (const [value, ls] of labelled) {
            const y = u.valToPos(value, 'y', true);
            ctx.fillStyle = ls[0].color;
            const who = ls.length === 1 ? ls[0].name : `${ls.length} channels`;
            ctx.fillText(`static ${fmt(value)} (${who})`, u.bbox.left + 4 * devicePixelRatio, y - 3 * devicePixelRatio);
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
    plots.push(new uPlot(opts, [time, ...list.map(s => s.values)], box));
  }
  window.addEventListener('resize', () => { for (const p of plots) p.setSize({ width: width(), height: 240 }); });
  return {
    plots,
    // (t) => every chart's cursor at t
    setTime(t) {
      quiet = true;
      for (const p of plots) p.setCursor({ left: p.valToPos(t, 'x'), top: p.bbox.height / devicePixelRatio / 2 });
      quiet = false;
    },
  };
}
