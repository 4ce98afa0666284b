// The walk in 3-D: reads the walk's JSON (lengths in whole millimetres, some columns delta-coded, see
// src/AcDream.App/Scenes/WalkPage.Data.cs), shows the frame chosen on the timeline and what its steps met.
// World axes: metres, X east, Y north, Z up.
import * as THREE from 'three';

const started = performance.now();
const data = JSON.parse(document.getElementById('walk-data').textContent);
const frames = data.frames;
const count = frames.count;
const m = (mm) => mm / 1000;

/** Undoes the delta coding: each value is the sum of the ones before it. */
function undelta(values) {
  const out = new Int32Array(values.length);
  let sum = 0;
  for (let i = 0; i < values.length; i++) { sum += values[i]; out[i] = sum; }
  return out;
}

const frameNumber = undelta(frames.frame);
const px = undelta(frames.x), py = undelta(frames.y), pz = undelta(frames.z);
const ex = undelta(frames.eyeX), ey = undelta(frames.eyeY), ez = undelta(frames.eyeZ);
// What the engine drew for each frame's move (PhysicsEngine.DrawMove): the segments of frame f are drawnAt[f] .. drawnAt[f] + drawnCount[f).
const drawnFrame = undelta(data.drawn.frame);
const drawnAt = new Map(), drawnCount = new Map();
drawnFrame.forEach((f, k) => {
  if (!drawnAt.has(f)) drawnAt.set(f, k);
  drawnCount.set(f, (drawnCount.get(f) || 0) + 1);
});
const creatures = data.creatures.map((c) => ({ id: c.id, frame: undelta(c.frame), x: undelta(c.x), y: undelta(c.y), z: undelta(c.z) }));

const mmText = (mm) => (mm / 1000).toFixed(3);
const normalText = (n, i) => `(${mmText(n[3 * i])}, ${mmText(n[3 * i + 1])}, ${mmText(n[3 * i + 2])})`;

/** What the frame's steps met, as text: the floor's and the wall's kind, id and normal. */
function metText(i) {
  const part = (name) => {
    const kind = data.kinds[frames[name + 'Kind'][i]];
    if (kind === 'None') return `${name}: none`;
    return `${name}: ${kind} ${frames.ids[frames[name + 'Id'][i]]}, normal ${normalText(frames[name + 'Normal'], i)}`;
  };
  return `${part('floor')}; ${part('wall')}`;
}

const timeline = document.getElementById('timeline');
timeline.max = String(count - 1);
const text = (id, value) => { document.getElementById(id).textContent = value; };
let current = 0;
let draw = () => {};

/** Shows sample i: the label, then the scene. */
function show(i) {
  current = Math.max(0, Math.min(count - 1, i));
  timeline.value = String(current);
  const cellName = frames.cellNames[frames.cell[current]];
  text('frame', `frame ${frameNumber[current]} of ${frameNumber[count - 1]}`);
  text('position', `(${mmText(px[current])}, ${mmText(py[current])}, ${mmText(pz[current])}) m`);
  text('cell', `cell ${frames.cellIds[frames.cell[current]]}${cellName ? ` (${cellName})` : ''}`);
  text('ground', frames.ground[current] ? 'on the ground' : 'in the air');
  text('outcome', `outcome: ${data.outcomes[frames.outcome[current]]}`);
  text('met', `met: ${metText(current)}`);
  draw();
}

timeline.addEventListener('input', () => show(Number(timeline.value)));
document.addEventListener('keydown', (e) => {
  const step = e.shiftKey ? 30 : 1;
  const to = { ArrowRight: current + step, ArrowLeft: current - step, Home: 0, End: count - 1 }[e.key];
  if (to !== undefined) { e.preventDefault(); show(to); }
});

// The scene. Without WebGL the label and the timeline still work.
try {
  draw = buildScene();
} catch (e) {
  text('message', `No 3-D view: ${e.message}`);
}
// A link may name a frame: page.html#frame=2200.
const linked = /frame=(\d+)/.exec(location.hash);
show(linked ? Math.max(0, frameNumber.indexOf(Number(linked[1]))) : 0);
window.walkPage = { ready: true, count, loadMs: performance.now() - started, show };

function buildScene() {
  const view = document.getElementById('view');
  // Smoothed edges on a GPU; not when WebGL is drawn in software (headless, no GPU), where they cost the most.
  let renderer = new THREE.WebGLRenderer({ antialias: false });
  const gl = renderer.getContext(), info = gl.getExtension('WEBGL_debug_renderer_info');
  if (info && !/SwiftShader|llvmpipe|software/i.test(String(gl.getParameter(info.UNMASKED_RENDERER_WEBGL)))) {
    renderer.dispose();
    renderer.forceContextLoss();
    renderer = new THREE.WebGLRenderer({ antialias: true });
  }
  renderer.setPixelRatio(window.devicePixelRatio);
  view.appendChild(renderer.domElement);
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0xdfe6ec);
  scene.add(new THREE.HemisphereLight(0xffffff, 0x8899aa, 2.2));
  const sun = new THREE.DirectionalLight(0xffffff, 1.2);
  sun.position.set(0.4, -0.6, 1);
  scene.add(sun);
  const camera = new THREE.PerspectiveCamera(55, 1, 0.05, 2000);
  camera.up.set(0, 0, 1);

  const point = (a, k) => new THREE.Vector3(m(a[k]), m(a[k + 1]), m(a[k + 2]));
  const points = (a) => { const out = []; for (let k = 0; k + 2 < a.length; k += 3) out.push(point(a, k)); return out; };

  /** Triangles (fans of the polygons) as one mesh, and their outlines as lines. */
  function polygons(list, colour, opacity, edges) {
    const tris = [], lines = [];
    for (const polygon of list) {
      const v = points(polygon);
      for (let k = 1; k + 1 < v.length; k++) tris.push(v[0], v[k], v[k + 1]);
      for (let k = 0; k < v.length; k++) lines.push(v[k], v[(k + 1) % v.length]);
    }
    const group = new THREE.Group();
    if (opacity > 0 && tris.length) {
      const mesh = new THREE.Mesh(new THREE.BufferGeometry().setFromPoints(tris),
        new THREE.MeshBasicMaterial({ color: colour, transparent: opacity < 1, opacity, side: THREE.DoubleSide, depthWrite: opacity >= 0.5 }));
      group.add(mesh);
    }
    if (edges && lines.length) {
      group.add(new THREE.LineSegments(new THREE.BufferGeometry().setFromPoints(lines), new THREE.LineBasicMaterial({ color: edges })));
    }
    return group;
  }

  /** Flat triangle lists (x, y, z × 3 each) as polygons of three. */
  const triangles = (flat) => { const out = []; for (let k = 0; k + 8 < flat.length; k += 9) out.push(flat.slice(k, k + 9)); return out; };

  // Surfaces by owner id (cells, objects, doors): where the contacts' surfaces are looked up.
  const owners = new Map();
  const own = (id, list, floors) => owners.set(id, { walls: list.map(points), floors: triangles(floors).map(points) });

  const cellColours = [0x42a5f5, 0x66bb6a, 0xffa726, 0xab47bc, 0x26a69a, 0xef5350, 0x8d6e63, 0x5c6bc0, 0xd4e157, 0xec407a];
  data.cells.forEach((cell, n) => {
    scene.add(polygons(triangles(cell.floors), cellColours[n % cellColours.length], 0.55, null));
    scene.add(polygons(cell.walls, 0x9e9e9e, 0.12, 0x555555));
    scene.add(polygons(cell.others, 0x9e9e9e, 0, 0xb0b0b0));
    own(cell.id, cell.walls.concat(cell.others), cell.floors);
  });

  for (const object of data.objects) {
    scene.add(polygons(triangles(object.floors), 0x8e24aa, 0.5, 0x6a1b9a));
    scene.add(polygons(object.walls, 0x8e24aa, object.building ? 0.06 : 0.2, 0xab47bc));
    for (const c of object.cylinders) {
      const bottom = point(c, 0), top = point(c, 3), height = Math.max(0.01, top.distanceTo(bottom));
      const mesh = new THREE.Mesh(new THREE.CylinderGeometry(m(c[6]), m(c[6]), height, 16).rotateX(Math.PI / 2),
        new THREE.MeshLambertMaterial({ color: 0x8e24aa, transparent: true, opacity: 0.4 }));
      mesh.position.copy(bottom).lerp(top, 0.5);
      scene.add(mesh);
    }
    own(object.id, object.walls, object.floors);
  }

  const doors = data.doors.map((door) => {
    const group = polygons(door.polygons, 0xe65100, 0.9, 0xbf360c);
    scene.add(group);
    own(door.id, door.polygons, []);
    return { group, states: door.states };
  });

  scene.add(terrain(data.terrain));

  // The route and the eye's path.
  const route = [], eyePath = [];
  for (let i = 0; i < count; i++) {
    route.push(new THREE.Vector3(m(px[i]), m(py[i]), m(pz[i]) + 0.02));
    eyePath.push(new THREE.Vector3(m(ex[i]), m(ey[i]), m(ez[i])));
  }
  scene.add(new THREE.Line(new THREE.BufferGeometry().setFromPoints(route), new THREE.LineBasicMaterial({ color: 0x212121 })));
  scene.add(new THREE.Line(new THREE.BufferGeometry().setFromPoints(eyePath), new THREE.LineBasicMaterial({ color: 0x00acc1, transparent: true, opacity: 0.35 })));

  // The player's body, the eye and its boom, the creatures.
  const cylinder = (colour, opacity) => {
    const geometry = new THREE.CylinderGeometry(data.radius, data.radius, data.height, 24).rotateX(Math.PI / 2).translate(0, 0, data.height / 2);
    const mesh = new THREE.Mesh(geometry, new THREE.MeshLambertMaterial({ color: colour, transparent: true, opacity }));
    mesh.add(new THREE.LineSegments(new THREE.EdgesGeometry(geometry, 30), new THREE.LineBasicMaterial({ color: colour })));
    scene.add(mesh);
    return mesh;
  };
  const body = cylinder(0x1e88e5, 0.55);
  const eye = new THREE.Mesh(new THREE.SphereGeometry(data.eyeRadius, 16, 12), new THREE.MeshLambertMaterial({ color: 0x00acc1 }));
  scene.add(eye);
  const boom = new THREE.Line(new THREE.BufferGeometry().setFromPoints([new THREE.Vector3(), new THREE.Vector3()]), new THREE.LineBasicMaterial({ color: 0x00838f }));
  scene.add(boom);
  const creatureBodies = creatures.map(() => cylinder(0x8d6e63, 0.5));

  // The contacts: an arrow along each normal, and the surface met drawn over.
  const wallArrow = new THREE.ArrowHelper(new THREE.Vector3(1, 0, 0), new THREE.Vector3(), 1, 0xe53935, 0.25, 0.15);
  const floorArrow = new THREE.ArrowHelper(new THREE.Vector3(0, 0, 1), new THREE.Vector3(), 1, 0x43a047, 0.25, 0.15);
  const wallMark = new THREE.Mesh(new THREE.BufferGeometry(), new THREE.MeshBasicMaterial({ color: 0xe53935, transparent: true, opacity: 0.6, side: THREE.DoubleSide, depthTest: false }));
  const floorMark = new THREE.Mesh(new THREE.BufferGeometry(), new THREE.MeshBasicMaterial({ color: 0x43a047, transparent: true, opacity: 0.7, side: THREE.DoubleSide, depthTest: false }));
  scene.add(wallArrow, floorArrow, wallMark, floorMark);

  // What the engine drew for the frame's move, in the colours of its kinds (the legend names them).
  const drawColours = { SubStep: 0x1e88e5, Contact: 0xe53935, Floor: 0x43a047, Support: 0x8e24aa, Edge: 0xfb8c00, Ceiling: 0x6d4c41 };
  const drawn = new THREE.LineSegments(new THREE.BufferGeometry(), new THREE.LineBasicMaterial({ vertexColors: true, depthTest: false }));
  drawn.renderOrder = 2;
  scene.add(drawn);

  // The view: orbiting the player (drag, wheel), or through the chase camera's eye.
  const orbit = { azimuth: -2.2, elevation: 0.9, distance: 13 };
  const eyeView = document.getElementById('eyeView');
  eyeView.addEventListener('change', () => draw());
  // The cut-away: nothing higher than 0.8 m above the head is drawn, so rooms and cellars show from above.
  const cut = document.getElementById('cut');
  cut.addEventListener('change', () => draw());
  const cutAway = new THREE.Plane(new THREE.Vector3(0, 0, -1), 0);
  let dragging = null;
  renderer.domElement.addEventListener('pointerdown', (e) => { dragging = { x: e.clientX, y: e.clientY }; });
  window.addEventListener('pointerup', () => { dragging = null; });
  window.addEventListener('pointermove', (e) => {
    if (!dragging) return;
    orbit.azimuth -= (e.clientX - dragging.x) * 0.01;
    orbit.elevation = Math.max(-1.4, Math.min(1.5, orbit.elevation + (e.clientY - dragging.y) * 0.01));
    dragging = { x: e.clientX, y: e.clientY };
    draw();
  });
  renderer.domElement.addEventListener('wheel', (e) => {
    e.preventDefault();
    orbit.distance = Math.max(1.5, Math.min(400, orbit.distance * Math.exp(e.deltaY * 0.001)));
    draw();
  }, { passive: false });
  window.addEventListener('resize', () => draw());

  let pending = false;
  return () => {
    if (!pending) { pending = true; requestAnimationFrame(render); }
  };

  function render() {
    pending = false;
    const i = current, f = frameNumber[i];
    const feet = new THREE.Vector3(m(px[i]), m(py[i]), m(pz[i]));
    body.position.copy(feet);
    eye.position.set(m(ex[i]), m(ey[i]), m(ez[i]));
    const pivot = feet.clone().add(new THREE.Vector3(0, 0, 1.5));
    boom.geometry.setFromPoints([pivot, eye.position]);
    creatures.forEach((c, n) => {
      const k = sampleAt(c.frame, f);
      creatureBodies[n].visible = k >= 0;
      if (k >= 0) creatureBodies[n].position.set(m(c.x[k]), m(c.y[k]), m(c.z[k]));
    });
    for (const door of doors) {
      let state = 'Closed';
      for (const [from, s] of door.states) if (from <= f) state = s;
      door.group.children[0].material.opacity = state === 'Closed' ? 0.9 : 0.2;
      door.group.children[0].material.transparent = state !== 'Closed';
    }
    contact('wall', i, feet, wallArrow, wallMark);
    contact('floor', i, feet, floorArrow, floorMark);
    drawFrame(f);

    const width = view.clientWidth, height = view.clientHeight;
    renderer.setSize(width, height);
    camera.aspect = width / Math.max(1, height);
    camera.updateProjectionMatrix();
    if (eyeView.checked) {
      camera.position.copy(eye.position);
      camera.lookAt(pivot);
    } else {
      const centre = feet.clone().add(new THREE.Vector3(0, 0, data.height / 2));
      const c = Math.cos(orbit.elevation);
      camera.position.set(centre.x + orbit.distance * c * Math.cos(orbit.azimuth), centre.y + orbit.distance * c * Math.sin(orbit.azimuth), centre.z + orbit.distance * Math.sin(orbit.elevation));
      camera.lookAt(centre);
    }
    cutAway.constant = feet.z + data.height + 0.8;
    renderer.clippingPlanes = cut.checked ? [cutAway] : [];
    renderer.render(scene, camera);
  }

  /** Loads frame f's drawn segments into the line set. */
  function drawFrame(f) {
    const at = drawnAt.get(f) ?? 0, n = drawnCount.get(f) ?? 0;
    const positions = new Float32Array(6 * n), colours = new Float32Array(6 * n);
    const colour = new THREE.Color();
    for (let k = 0; k < n; k++) {
      for (let j = 0; j < 6; j++) positions[6 * k + j] = m(data.drawn.ends[6 * (at + k) + j]);
      colour.setHex(drawColours[data.drawn.kinds[data.drawn.kind[at + k]]] ?? 0x000000);
      for (let j = 0; j < 2; j++) colours.set([colour.r, colour.g, colour.b], 6 * k + 3 * j);
    }
    drawn.geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
    drawn.geometry.setAttribute('color', new THREE.BufferAttribute(colours, 3));
    drawn.geometry.computeBoundingSphere();
    text('drawn', `drawn by the engine: ${n} segments (blue sub-steps, red contacts, green floor, purple support, orange edge, brown ceiling)`);
  }

  /** The arrow along the contact's normal at the body's side (a wall) or its feet (a floor), and the polygon met. */
  function contact(name, i, feet, arrow, mark) {
    const kind = data.kinds[frames[name + 'Kind'][i]];
    const n = frames[name + 'Normal'];
    const normal = new THREE.Vector3(m(n[3 * i]), m(n[3 * i + 1]), m(n[3 * i + 2]));
    arrow.visible = kind !== 'None' && normal.lengthSq() > 0;
    mark.visible = false;
    if (!arrow.visible) return;
    normal.normalize();
    const at = name === 'wall'
      ? feet.clone().addScaledVector(new THREE.Vector3(normal.x, normal.y, 0).normalize(), -data.radius).add(new THREE.Vector3(0, 0, data.height / 2))
      : feet.clone();
    arrow.position.copy(at);
    arrow.setDirection(normal);
    const owner = owners.get(frames.ids[frames[name + 'Id'][i]]);
    const polygon = owner && (name === 'floor' ? under(owner.floors, at) : nearest(owner.walls, at, normal));
    if (polygon) {
      const tris = [];
      for (let k = 1; k + 1 < polygon.length; k++) tris.push(polygon[0], polygon[k], polygon[k + 1]);
      mark.geometry.dispose();
      mark.geometry = new THREE.BufferGeometry().setFromPoints(tris);
      mark.visible = true;
    }
  }
}

/** The polygon facing along ±normal (within about 25°) nearest to the point: its plane's distance, then its centre's. */
function nearest(list, at, normal) {
  let best = null, bestScore = Infinity;
  for (const v of list) {
    if (v.length < 3) continue;
    const pn = new THREE.Vector3().subVectors(v[1], v[0]).cross(new THREE.Vector3().subVectors(v[2], v[0])).normalize();
    if (Math.abs(pn.dot(normal)) < 0.9) continue;
    const centre = v.reduce((s, p) => s.add(p), new THREE.Vector3()).divideScalar(v.length);
    const score = Math.abs(pn.dot(new THREE.Vector3().subVectors(at, v[0]))) + 0.1 * centre.distanceTo(at);
    if (score < bestScore) { bestScore = score; best = v; }
  }
  return best;
}

/** The floor triangle under the point, seen from above, nearest below or above it; null when none is. */
function under(list, at) {
  let best = null, bestGap = Infinity;
  for (const [a, b, c] of list) {
    const d = (b.y - c.y) * (a.x - c.x) + (c.x - b.x) * (a.y - c.y);
    if (Math.abs(d) < 1e-9) continue;
    const u = ((b.y - c.y) * (at.x - c.x) + (c.x - b.x) * (at.y - c.y)) / d;
    const v = ((c.y - a.y) * (at.x - c.x) + (a.x - c.x) * (at.y - c.y)) / d;
    if (u < -1e-3 || v < -1e-3 || u + v > 1 + 1e-3) continue;
    const gap = Math.abs(u * a.z + v * b.z + (1 - u - v) * c.z - at.z);
    if (gap < bestGap) { bestGap = gap; best = [a, b, c]; }
  }
  return best;
}

/** The index of frame f in a creature's frames (increasing), or −1 when it was not in the world then. */
function sampleAt(list, f) {
  let lo = 0, hi = list.length - 1;
  while (lo <= hi) {
    const mid = (lo + hi) >> 1;
    if (list[mid] === f) return mid;
    if (list[mid] < f) lo = mid + 1; else hi = mid - 1;
  }
  return -1;
}

/** The terrain patch: a grid of heights, shaded, half see-through so the cellars below it show. */
function terrain(t) {
  const z = undelta(t.z);
  const positions = new Float32Array(t.nx * t.ny * 3);
  for (let j = 0; j < t.ny; j++) {
    for (let i = 0; i < t.nx; i++) {
      const k = j * t.nx + i;
      positions.set([t.x0 + i * t.step, t.y0 + j * t.step, z[k] / 1000], 3 * k);
    }
  }
  const index = [];
  for (let j = 0; j + 1 < t.ny; j++) {
    for (let i = 0; i + 1 < t.nx; i++) {
      const a = j * t.nx + i, b = a + 1, c = a + t.nx, d = c + 1;
      index.push(a, b, d, a, d, c);
    }
  }
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
  geometry.setIndex(index);
  geometry.computeVertexNormals();
  return new THREE.Mesh(geometry, new THREE.MeshLambertMaterial({ color: 0xa5b889, transparent: true, opacity: 0.45, side: THREE.DoubleSide, depthWrite: false }));
}
