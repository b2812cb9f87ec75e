// The 3D replay (three.js): replay.glb's bodies (one mesh each) posed at the report's time from
// its animation tracks, the ropes as lines through their attachment points, a ground grid; for a
// floating scene the still-water surface, for a scene with contact the contact force on each
// body as an arrow (overlays.js).
import {
  AmbientLight, Box3, BufferGeometry, Color, DirectionalLight, Float32BufferAttribute, GridHelper,
  HemisphereLight, Line, LineBasicMaterial, PerspectiveCamera, Scene, Vector3, WebGLRenderer,
} from 'three';
import { contactArrows, waterSurface } from './overlays.js';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';

// (glb bytes, container, overlays {water: level in m or null, contacts: [{name, values, point}], time})
// => Promise of {bodies, setTime(t), render(), scene, duration, water, arrows}
export function makeReplay(glb, container, overlays = {}) {
  return new Promise((resolve, reject) => {
    const buffer = glb.buffer.slice(glb.byteOffset, glb.byteOffset + glb.byteLength);
    new GLTFLoader().parse(buffer, '', gltf => {
      try { resolve(build(gltf, container, overlays)); } catch (e) { reject(e); }
    }, reject);
  });
}

function build(gltf, container, overlays) {
  const scene = new Scene();
  scene.background = new Color(0xe9eef3);
  scene.add(gltf.scene);
  scene.add(new HemisphereLight(0xffffff, 0x8090a0, 1.6), new AmbientLight(0xffffff, 0.4));
  const sun = new DirectionalLight(0xffffff, 1.8);
  sun.position.set(3, 10, 6);
  scene.add(sun);
  // (nodes with extras.body) => the bodies, in replay.glb's order
  const bodies = [];
  gltf.scene.traverse(o => { if (o.userData && o.userData.body !== undefined) bodies.push(o); });
  const world = bodies.length ? bodies[0].parent : gltf.scene;
  // (animation tracks) => per object a position and a quaternion interpolant
  const tracks = [];
  let duration = 0;
  for (const clip of gltf.animations) {
    duration = Math.max(duration, clip.duration);
    for (const track of clip.tracks) {
      const dot = track.name.lastIndexOf('.');
      const target = gltf.scene.getObjectByName(track.name.slice(0, dot));
      const property = track.name.slice(dot + 1);
      if (target && (property === 'position' || property === 'quaternion'))
        tracks.push({ target, property, interpolant: track.createInterpolant() });
    }
  }
  // (ropes in the scene's extras) => one line each
  const ropeSpecs = (gltf.scene.userData && gltf.scene.userData.yardsim_ropes) || [];
  const ropes = ropeSpecs.map(spec => {
    const geometry = new BufferGeometry();
    geometry.setAttribute('position', new Float32BufferAttribute(new Float32Array(3 * spec.points.length), 3));
    const line = new Line(geometry, new LineBasicMaterial({ color: 0x202020 }));
    line.name = `rope:${spec.name}`;
    line.frustumCulled = false;
    scene.add(line);
    return { spec, line };
  });
  const v = new Vector3();
  function placeRopes() {
    gltf.scene.updateMatrixWorld(true);
    for (const { spec, line } of ropes) {
      const pos = line.geometry.attributes.position;
      spec.points.forEach((p, i) => {
        v.set(p.p[0], p.p[1], p.p[2]);
        (p.node >= 0 ? bodies[p.node] : world).localToWorld(v);
        pos.setXYZ(i, v.x, v.y, v.z);
      });
      pos.needsUpdate = true;
      line.geometry.computeBoundingSphere();
    }
  }
  function setTime(t) {
    for (const { target, property, interpolant } of tracks) {
      const r = interpolant.evaluate(t);
      if (property === 'position') target.position.fromArray(r);
      else target.quaternion.fromArray(r).normalize();
    }
    placeRopes();
  }
  setTime(0);
  // (bodies over the whole run) => camera and grid that frame them
  const bounds = new Box3();
  const frames = tracks.length ? tracks[0].interpolant.parameterPositions.length : 1;
  const times = tracks.length ? tracks[0].interpolant.parameterPositions : [0];
  for (let k = 0; k < frames; k += Math.max(1, Math.floor(frames / 50))) {
    setTime(times[k]);
    gltf.scene.updateMatrixWorld(true);
    for (const b of bodies) bounds.expandByObject(b);
    for (const { line } of ropes) bounds.expandByObject(line);
  }
  setTime(0);
  const size = bounds.getSize(new Vector3());
  const centre = bounds.getCenter(new Vector3());
  const radius = Math.max(size.length() / 2, 0.5);
  // (extent) => a ground grid about four radii wide, in round metres, 20 divisions
  const decade = Math.pow(10, Math.floor(Math.log10(radius * 4)));
  const gridSize = Math.ceil((radius * 4) / decade) * decade;
  const grid = new GridHelper(gridSize, 20, 0x9aa5b1, 0xc5ccd3);
  grid.position.set(centre.x, Math.min(0, bounds.min.y), centre.z);
  scene.add(grid);
  const water = overlays.water !== null && overlays.water !== undefined ? waterSurface(scene, world, overlays.water, centre, gridSize) : null;
  const arrows = contactArrows(scene, world, bodies, overlays.contacts || [], overlays.time, radius);
  const camera = new PerspectiveCamera(40, 1, radius / 100, radius * 100);
  camera.position.copy(centre).add(new Vector3(0.8, 0.45, 1.6).normalize().multiplyScalar(radius * 2.6));
  const renderer = new WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(window.devicePixelRatio);
  container.append(renderer.domElement);
  const controls = new OrbitControls(camera, renderer.domElement);
  controls.target.copy(centre);
  function resize() {
    const w = container.clientWidth, h = container.clientHeight;
    renderer.setSize(w, h);
    camera.aspect = w / h;
    camera.updateProjectionMatrix();
    render();
  }
  function render() { controls.update(); renderer.render(scene, camera); }
  controls.addEventListener('change', () => renderer.render(scene, camera));
  window.addEventListener('resize', resize);
  resize();
  return { bodies, duration, scene, water, arrows, setTime(t) { setTime(t); arrows.setTime(t); render(); } };
}
