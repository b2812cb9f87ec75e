// What the replay draws besides the bodies and ropes: the still-water surface of a floating
// scene (a translucent plane at the water level, the size of the ground grid) and the contact
// force on each body of a collision set (its `<set>.<body>.fz` channel, world z) as an arrow,
// its length proportional to the force, ending where the force acts (its `<set>.<body>.px|py|pz`
// channels, marked by a dot) or, without those, against the body's bottom (pushed up) or top
// (pushed down).
import {
  ArrowHelper, DoubleSide, Mesh, MeshBasicMaterial, MeshStandardMaterial, PlaneGeometry, SphereGeometry, Vector3, Box3,
} from 'three';

// (scene, the z-up world node, level in m, centre of the bodies' bounds, the ground grid's size)
// => the plane
export function waterSurface(scene, world, level, centre, size) {
  const plane = new Mesh(new PlaneGeometry(size, size),
    new MeshStandardMaterial({ color: 0x2f7fbf, transparent: true, opacity: 0.35, side: DoubleSide, depthWrite: false }));
  plane.name = 'water';
  plane.rotation.x = -Math.PI / 2;  // three.js is y-up: the plane's normal along +y
  world.updateMatrixWorld(true);
  const at = world.localToWorld(new Vector3(0, 0, level));
  plane.position.set(centre.x, at.y, centre.z);
  plane.renderOrder = 1;
  scene.add(plane);
  return plane;
}

// (time, values, t) => the value at t, linear between samples
function at(time, values, t) {
  let lo = 0, hi = time.length - 1;
  if (hi < 0) return 0;
  if (t <= time[0]) return values[0];
  if (t >= time[hi]) return values[hi];
  while (hi - lo > 1) { const mid = (lo + hi) >> 1; if (time[mid] <= t) lo = mid; else hi = mid; }
  const w = (t - time[lo]) / (time[hi] - time[lo]);
  return values[lo] * (1 - w) + values[hi] * w;
}

// (time, values, t) => the value at t, linear between samples; NaN next to a sample that is not
// finite (no contact: the point of application is null)
function atFinite(time, values, t) {
  let lo = 0, hi = time.length - 1;
  if (hi < 0) return NaN;
  if (t <= time[0]) hi = 0;
  else if (t >= time[hi]) lo = hi;
  else while (hi - lo > 1) { const mid = (lo + hi) >> 1; if (time[mid] <= t) lo = mid; else hi = mid; }
  const a = values[lo], b = values[hi];
  if (!Number.isFinite(a) || !Number.isFinite(b)) return NaN;
  const w = hi === lo ? 0 : (t - time[lo]) / (time[hi] - time[lo]);
  return a * (1 - w) + b * w;
}

// (scene, the z-up world node, bodies, contact channels [{name, values, point: [px, py, pz] value
// arrays or null}], time, scene radius) => {list, setTime(t)}
export function contactArrows(scene, world, bodies, channels, time, radius) {
  const list = [];
  for (const c of channels) {
    // (<set>.<body>.fz) => the body with the longest matching name
    const body = bodies.filter(b => c.name.endsWith(`.${b.userData.body}.fz`))
      .sort((a, b) => b.userData.body.length - a.userData.body.length)[0];
    if (!body) continue;
    let max = 0;
    for (const v of c.values) if (Number.isFinite(v)) max = Math.max(max, Math.abs(v));
    if (!(max > 0)) continue;
    const arrow = new ArrowHelper(new Vector3(0, 1, 0), new Vector3(), 1, 0xe8590c, 0.3, 0.18);
    arrow.name = `contact:${c.name}`;
    arrow.visible = false;
    scene.add(arrow);
    const dot = new Mesh(new SphereGeometry(0.015 * radius, 12, 8), new MeshBasicMaterial({ color: 0xe8590c }));
    dot.name = `contact-point:${c.name}`;
    dot.visible = false;
    scene.add(dot);
    list.push({ channel: c.name, body, max, values: c.values, point: c.point || null, arrow, dot, force: 0, at: null });
  }
  const box = new Box3();
  const centre = new Vector3();
  return {
    list,
    // (t) => each arrow with the force then, ending at its point of application (a dot there)
    // or at its body; hidden below 1e-3 of its largest
    setTime(t) {
      world.updateMatrixWorld(true);
      for (const a of list) {
        const f = at(time, a.values, t);
        a.force = f;
        a.arrow.visible = Math.abs(f) > 1e-3 * a.max;
        const p = a.point && a.point.map(v => atFinite(time, v, t));
        a.at = p && p.every(Number.isFinite) ? world.localToWorld(new Vector3(p[0], p[1], p[2])) : null;
        a.dot.visible = a.arrow.visible && a.at !== null;
        if (!a.arrow.visible) continue;
        const len = Math.max(0.05, 0.35 * radius * Math.abs(f) / a.max);
        const up = f > 0;
        if (a.at) {
          a.dot.position.copy(a.at);
          a.arrow.position.set(a.at.x, up ? a.at.y - len : a.at.y + len, a.at.z);
        } else {
          box.setFromObject(a.body);
          box.getCenter(centre);
          a.arrow.position.set(centre.x, up ? box.min.y - len : box.max.y + len, centre.z);
        }
        a.arrow.setDirection(new Vector3(0, up ? 1 : -1, 0));
        a.arrow.setLength(len, Math.min(0.3 * len, 0.1 * radius), Math.min(0.18 * len, 0.06 * radius));
      }
    },
  };
}
