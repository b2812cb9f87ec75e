// What a reviewer reads: channels sorted into quantity groups (rope tensions, heights, heel and
// trim, draft, contact forces, clearances, ...) from their name and SI unit, each group shown in
// one engineering unit chosen by its magnitude (kN or MN, t, degrees, mm or m, ...), and numbers
// without floating-point noise. The CSV stays SI; only the page converts.

// (channel name, SI unit, the collision sets' prefixes "<set>.") => the quantity group's title
// and the axis' quantity name
export function quantityGroup(name, unit, contactSets = []) {
  const leaf = name.slice(name.lastIndexOf('.') + 1);
  const has = re => re.test(name);
  switch (unit) {
    case 'N':
      if (leaf === 'tension' || leaf === 'peak_tension') return { title: 'Rope tensions', quantity: 'tension' };
      if (contactSets.some(p => name.startsWith(p)) || has(/contact/)) return { title: 'Contact forces', quantity: 'force' };
      if (has(/hook_load|load$/)) return { title: 'Loads', quantity: 'load' };
      if (leaf === 'reaction') return { title: 'Joint reactions', quantity: 'force' };
      return { title: 'Forces', quantity: 'force' };
    case 'N m': case 'N*m': case 'Nm': return { title: 'Moments', quantity: 'moment' };
    case 'rad':
      if (leaf === 'roll' || leaf === 'pitch' || has(/heel|trim/)) return { title: 'Heel and trim', quantity: 'angle' };
      if (leaf === 'yaw') return { title: 'Headings', quantity: 'angle' };
      if (leaf === 'q') return { title: 'Joint angles', quantity: 'angle' };
      return { title: 'Angles', quantity: 'angle' };
    case 'rad/s': return { title: 'Angular rates', quantity: 'rate' };
    case 'm':
      if (leaf === 'distance' || has(/clearance/)) return { title: 'Clearances', quantity: 'distance' };
      if (has(/draft/)) return { title: 'Draft', quantity: 'draft' };
      if (/^gm_/.test(leaf)) return { title: 'Metacentric heights', quantity: 'GM' };
      if (leaf === 'z' || has(/height/)) return { title: 'Heights', quantity: 'z' };
      if (leaf === 'x' || leaf === 'y') return { title: 'Horizontal positions', quantity: 'position' };
      if (leaf === 'q') return { title: 'Joint travels', quantity: 'travel' };
      return { title: 'Lengths', quantity: 'length' };
    case 'm/s': return { title: 'Speeds', quantity: 'speed' };
    case 'm/s^2': return { title: 'Accelerations', quantity: 'acceleration' };
    case 'rad/s^2': return { title: 'Angular accelerations', quantity: 'angular acceleration' };
    case 'm^2': return { title: 'Areas', quantity: 'area' };
    case 'm^3': return { title: 'Volumes', quantity: 'volume' };
    case 'kg': return { title: 'Masses', quantity: 'mass' };
    case 'J': return { title: 'Energy', quantity: 'energy' };
    case 'W': return { title: 'Power', quantity: 'power' };
    case 'Pa': return { title: 'Pressures', quantity: 'pressure' };
    case '-': case '': case '1': return { title: 'Counts and ratios', quantity: 'value' };
    default: return { title: `Quantities in ${unit}`, quantity: 'value' };
  }
}

// SI unit => the display units to choose from by magnitude (largest first): [unit, factor]
const ladders = {
  N: [['MN', 1e-6, 1e6], ['kN', 1e-3, 1e3], ['N', 1, 0]],
  'N m': [['MN m', 1e-6, 1e6], ['kN m', 1e-3, 1e3], ['N m', 1, 0]],
  kg: [['t', 1e-3, 1e3], ['kg', 1, 0]],
  J: [['MJ', 1e-6, 1e6], ['kJ', 1e-3, 1e3], ['J', 1, 0]],
  W: [['MW', 1e-6, 1e6], ['kW', 1e-3, 1e3], ['W', 1, 0]],
  Pa: [['MPa', 1e-6, 1e6], ['kPa', 1e-3, 1e3], ['Pa', 1, 0]],
  m: [['m', 1, 0.1], ['mm', 1e3, 0]],
};
ladders['N*m'] = ladders.Nm = ladders['N m'];

// (SI unit, largest magnitude in it) => {unit, factor}: display value = SI value × factor
export function displayUnit(unit, maxAbs) {
  if (unit === 'rad') return { unit: 'deg', factor: 180 / Math.PI };
  if (unit === 'rad/s') return { unit: 'deg/s', factor: 180 / Math.PI };
  if (unit === 'rad/s^2') return { unit: 'deg/s^2', factor: 180 / Math.PI };
  const ladder = ladders[unit];
  if (!ladder) return { unit: unit || '-', factor: 1 };
  const m = Number.isFinite(maxAbs) ? maxAbs : 0;
  if (!(m > 0)) return { unit, factor: 1 };  // nothing but zeros: the SI unit
  for (const [u, factor, from] of ladder) if (m >= from) return { unit: u, factor };
  return { unit: ladder[ladder.length - 1][0], factor: ladder[ladder.length - 1][1] };
}

// (values) => the largest finite magnitude
export function maxAbs(values) {
  let m = 0;
  for (const v of values) if (Number.isFinite(v) && Math.abs(v) > m) m = Math.abs(v);
  return m;
}

// (values, factor, the scale of the quantity in this run) => the display values, those below
// 1e-9 of the channel's largest magnitude or of that scale shown as 0 (a value that is 0 up to
// round-off: 3e-22 N on a channel, or a whole channel of 1e-11 N in a run of 100 kN forces)
export function cleaned(values, factor, scale = 0) {
  const out = new Float64Array(values.length);
  const floor = 1e-9 * Math.max(maxAbs(values), scale);
  for (let i = 0; i < values.length; i++) {
    const v = values[i];
    out[i] = Number.isFinite(v) ? (Math.abs(v) <= floor ? 0 : v * factor) : NaN;
  }
  return out;
}

// (number, significant digits, the scale of its neighbours) => short text, 0 when it is below
// 1e-9 of that scale; exponents only outside 1e-3..1e6
export function num(x, digits = 4, scale = Math.abs(x)) {
  if (x === null || x === undefined || !Number.isFinite(x)) return '–';
  if (Math.abs(x) <= 1e-9 * scale) return '0';
  const a = Math.abs(x);
  if (a >= 1e6 || a < 1e-3) return x.toExponential(digits - 1).replace('e+', 'e');
  return Number(x.toPrecision(digits)).toString();
}

// (tick values) => labels with the decimals their spacing needs, 0 for a tick at round-off
export function tickLabels(ticks) {
  if (!ticks.length) return [];
  const step = ticks.length > 1 ? Math.abs(ticks[1] - ticks[0]) : Math.abs(ticks[0]) || 1;
  const big = Math.max(...ticks.map(Math.abs));
  if (big >= 1e6 || (step > 0 && step < 1e-4)) return ticks.map(v => (Math.abs(v) < step * 1e-6 ? '0' : v.toExponential(2).replace('e+', 'e')));
  // (spacing) => the fewest decimals that write it exactly (2.5 needs 1)
  let decimals = 0;
  while (decimals < 6 && Math.abs(step * 10 ** decimals - Math.round(step * 10 ** decimals)) > 1e-6 * step * 10 ** decimals) decimals++;
  return ticks.map(v => (Math.abs(v) < step * 1e-6 ? '0' : v.toFixed(decimals)));
}

// (series [{name, unit, values}], every recorded series) => groups in a fixed order, each
// {title, quantity, si, unit, factor, scale (the largest SI magnitude of its unit in the run),
// list}; the unit chosen from every recorded channel of the
// group, so that the header's table and the plots say the same
export function groupSeries(series, recorded = series) {
  // (a `<set>.normal_force` channel) => a collision set, whose `<set>.<body>.fz` are contact forces
  const sets = recorded.filter(s => /\.normal_force$/.test(s.name)).map(s => s.name.replace(/normal_force$/, ''));
  const group = s => quantityGroup(s.name, s.unit, sets);
  const key = s => `${group(s).title}|${s.unit}`;
  const magnitude = new Map(), perUnit = new Map();
  for (const s of recorded) {
    const m = maxAbs(s.values);
    magnitude.set(key(s), Math.max(magnitude.get(key(s)) || 0, m));
    perUnit.set(s.unit, Math.max(perUnit.get(s.unit) || 0, m));
  }
  const groups = new Map();
  for (const s of series) {
    const k = key(s);
    if (!groups.has(k)) {
      const g = group(s);
      // (the group's magnitude; 0 up to round-off against the run's largest of its unit: 0)
      const m = magnitude.get(k) <= 1e-9 * perUnit.get(s.unit) ? 0 : magnitude.get(k);
      groups.set(k, { ...g, si: s.unit, scale: perUnit.get(s.unit), ...displayUnit(s.unit, m), list: [] });
    }
    groups.get(k).list.push(s);
  }
  const order = ['Rope tensions', 'Loads', 'Heights', 'Horizontal positions', 'Heel and trim', 'Headings', 'Draft',
    'Metacentric heights', 'Joint angles', 'Joint travels', 'Contact forces', 'Clearances', 'Joint reactions', 'Forces', 'Moments'];
  const rank = g => { const i = order.indexOf(g.title); return i < 0 ? order.length : i; };
  return [...groups.values()].sort((a, b) => rank(a) - rank(b));
}
