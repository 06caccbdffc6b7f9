// Loads a .glb with three.js's GLTFLoader under Node and prints, as JSON, what it makes of the
// leaf tints (glTF COLOR_0): per mesh with a colour attribute, its item size, whether it is
// normalized, whether the material multiplies by it (vertexColors), the distinct colours and
// the smallest green. Usage: node leaf-tints.mjs FILE.glb
import { loadGltf } from './load-gltf.mjs';

const gltf = await loadGltf(process.argv[2]);
const meshes = [];
gltf.scene.traverse((o) => {
  if (!o.isMesh) return;
  const color = o.geometry.getAttribute('color');
  const materials = Array.isArray(o.material) ? o.material : [o.material];
  const entry = { name: o.name, material: materials.map((m) => m.name).join(','), color: !!color };
  if (color) {
    const seen = new Set();
    let minGreen = 1;
    // Only the vertices this primitive draws (glTF primitives share one vertex set).
    const index = o.geometry.getIndex();
    const count = index ? index.count : color.count;
    for (let k = 0; k < count; k++) {
      const i = index ? index.getX(k) : k;
      const r = color.getX(i), g = color.getY(i), b = color.getZ(i);
      seen.add(`${r.toFixed(4)},${g.toFixed(4)},${b.toFixed(4)}`);
      minGreen = Math.min(minGreen, g);
    }
    Object.assign(entry, {
      itemSize: color.itemSize, normalized: color.normalized,
      vertexColors: materials.every((m) => m.vertexColors), distinct: seen.size, minGreen,
    });
  }
  meshes.push(entry);
});
console.log(JSON.stringify({ meshes }));
