// A sweep's page (sweep.html of `yardsim sweep`): the case table (sorted by a click on a column,
// filtered by text), each collected quantity against each varied parameter with its limit, and
// the operability map: pass or fail of every case over two varied parameters.
import { el, fmt } from './data.js';

const NS = 'http://www.w3.org/2000/svg';
// (tag, attributes) => SVG element
function svg(tag, attrs = {}) {
  const e = document.createElementNS(NS, tag);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
  return e;
}

// (values) => [lo, hi] with a margin, never empty
function range(vs) {
  const f = vs.filter(Number.isFinite);
  let lo = f.length ? Math.min(...f) : 0, hi = f.length ? Math.max(...f) : 1;
  if (lo === hi) { lo -= Math.abs(lo) * 0.1 || 1; hi += Math.abs(hi) * 0.1 || 1; }
  const m = (hi - lo) * 0.06;
  return [lo - m, hi + m];
}

// (title, x label, y label, points [{x, y, pass, id}], horizontal line or null) => an SVG scatter plot
function scatter(title, xl, yl, points, hline) {
  const W = 420, H = 300, L = 70, R = 12, T = 10, B = 42;
  const [x0, x1] = range(points.map(p => p.x));
  const [y0, y1] = range(points.map(p => p.y).concat(hline === null ? [] : [hline]));
  const sx = x => L + (x - x0) / (x1 - x0) * (W - L - R), sy = y => H - B - (y - y0) / (y1 - y0) * (H - T - B);
  const s = svg('svg', { width: W, height: H, class: 'scatter' });
  s.append(svg('rect', { x: L, y: T, width: W - L - R, height: H - T - B, fill: '#fff', stroke: '#d8dee4' }));
  for (let i = 0; i <= 4; i++) {
    const xv = x0 + (x1 - x0) * i / 4, yv = y0 + (y1 - y0) * i / 4;
    const tx = svg('text', { x: sx(xv), y: H - B + 14, 'text-anchor': 'middle', 'font-size': 10 }); tx.textContent = fmt(xv, 3);
    const ty = svg('text', { x: L - 4, y: sy(yv) + 3, 'text-anchor': 'end', 'font-size': 10 }); ty.textContent = fmt(yv, 3);
    s.append(tx, ty);
  }
  const lx = svg('text', { x: (L + W - R) / 2, y: H - 6, 'text-anchor': 'middle', 'font-size': 11 }); lx.textContent = xl;
  const ly = svg('text', { x: 12, y: (T + H - B) / 2, 'text-anchor': 'middle', 'font-size': 11, transform: `rotate(-90 12 ${(T + H - B) / 2})` });
  ly.textContent = yl;
  s.append(lx, ly);
  if (hline !== null) s.append(svg('line', { x1: L, x2: W - R, y1: sy(hline), y2: sy(hline), stroke: '#cf222e', 'stroke-dasharray': '5 3', class: 'limit' }));
  for (const p of points) {
    if (!Number.isFinite(p.x) || !Number.isFinite(p.y)) continue;
    const c = svg('circle', { cx: sx(p.x), cy: sy(p.y), r: 4, fill: p.pass ? '#1a7f37' : '#cf222e', 'fill-opacity': 0.75, class: p.pass ? 'pass' : 'fail' });
    const tip = svg('title'); tip.textContent = `case ${p.id}: ${fmt(p.x)}, ${fmt(p.y)}`;
    c.append(tip);
    s.append(c);
  }
  return el('div', { class: 'plot' }, el('h3', {}, title), s);
}

// (data, root) => the case table with sort and filter
function caseTable(data, root) {
  const cols = [['case', r => r.id], ...data.params.map((p, i) => [p, r => r.values[i]]), ['status', r => r.status],
    ['pass', r => (r.pass ? 'pass' : 'fail')], ['wall [s]', r => r.wall], ...data.collect.map((c, i) => [c, r => r.collected[i]])];
  const filter = el('input', { type: 'search', id: 'case-filter', placeholder: 'filter cases (text in any column)' });
  const table = el('table', { id: 'cases', class: 'cases' });
  const head = el('tr', {});
  let key = -1, dir = 1;  // -1: the cases in their order
  cols.forEach(([name], k) => {
    const th = el('th', { 'data-col': String(k) }, name);
    th.addEventListener('click', () => { dir = key === k ? -dir : 1; key = k; draw(); });
    head.append(th);
  });
  const body = el('tbody', {});
  table.append(el('thead', {}, head), body);
  const cell = v => (typeof v === 'number' || v === null ? el('td', { class: 'num' }, fmt(v, 5)) : el('td', {}, v));
  function draw() {
    const q = filter.value.trim().toLowerCase();
    const rows = key < 0 ? data.rows : data.rows.slice().sort((a, b) => {
      const x = cols[key][1](a), y = cols[key][1](b);
      return (x < y ? -1 : x > y ? 1 : 0) * dir;
    });
    body.replaceChildren();
    for (const r of rows) {
      const tds = cols.map(([, get]) => cell(get(r)));
      if (q && !tds.some(td => td.textContent.toLowerCase().includes(q)) && !r.message.toLowerCase().includes(q)) continue;
      const tr = el('tr', { class: r.pass ? 'pass' : 'fail' }, ...tds);
      if (r.link) tds[0].replaceChildren(el('a', { href: r.link }, String(r.id)));
      if (r.message) tr.title = r.message;
      body.append(tr);
    }
  }
  filter.addEventListener('input', draw);
  draw();
  root.append(el('h2', {}, 'Cases'), filter, table);
  return { draw, filter, table };
}

export function renderSweep(data, root) {
  root.append(el('h1', {}, data.title));
  const facts = el('table', { class: 'run-facts' });
  for (const [k, v] of data.facts) facts.append(el('tr', {}, el('th', {}, k), el('td', {}, v)));
  root.append(facts);
  const worst = data.rows.filter(r => r.link);
  if (worst.length) {
    const list = el('ul', { id: 'worst' });
    for (const r of worst) list.append(el('li', {}, el('a', { href: r.link }, `case ${r.id}`), ` (${r.status})`));
    root.append(el('h2', {}, 'Worst cases'), list);
  }
  const box = el('div', { class: 'plots', id: 'operability' });
  if (data.operability.length === 2) {
    const [a, b] = data.operability.map(n => data.params.indexOf(n));
    const pts = data.rows.filter(r => r.status !== 'missing').map(r => ({ x: r.values[a], y: r.values[b], pass: r.pass, id: r.id }));
    const lims = data.limits.map(l => `${l.collect} ${l.upper ? '≤' : '≥'} ${fmt(l.bound)}`).join(', ') || 'status ok';
    box.append(scatter(`operability: green within ${lims}, red not`, data.operability[0], data.operability[1], pts, null));
  }
  root.append(el('h2', {}, 'Operability'), box);
  const plots = el('div', { class: 'plots', id: 'plots' });
  data.collect.forEach((c, k) => {
    const lim = data.limits.find(l => l.collect === c);
    data.params.forEach((p, i) => {
      const pts = data.rows.map(r => ({ x: r.values[i], y: r.collected[k], pass: r.pass, id: r.id }));
      plots.append(scatter(`${c} against ${p}`, p, c, pts, lim ? lim.bound : null));
    });
  });
  root.append(el('h2', {}, 'Collected against varied'), plots);
  return caseTable(data, root);
}
