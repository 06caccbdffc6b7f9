// Loads a Sylva LOD chain (.glb, `sylva-cli lods`) with three.js's GLTFLoader under Node and
// follows MSFT_lod the way a loader plugin does: the scene's node, then every node its
// MSFT_lod.ids name, each loaded through the parser (three.js has no built-in MSFT_lod). Prints
// JSON: levels [{name, triangles, material}] in chain order and the MSFT_screencoverage list.
// Usage: node lod-levels.mjs FILE.glb
import { loadGltf } from './load-gltf.mjs';

const file = process.argv[2];
const gltf = await loadGltf(file);

const json = gltf.parser.json;
const topIndex = json.scenes[json.scene ?? 0].nodes[0];
const top = json.nodes[topIndex];
const ids = [topIndex, ...(top.extensions?.MSFT_lod?.ids ?? [])];
const levels = [];
for (const id of ids) {
  const node = await gltf.parser.getDependency('node', id);
  let triangles = 0;
  let material = '';
  node.traverse((o) => {
    if (!o.isMesh) return;
    const g = o.geometry;
    triangles += (g.index ? g.index.count : g.attributes.position.count) / 3;
    material = material || o.material?.name || '';
  });
  levels.push({ name: node.name, triangles, material });
}
console.log(JSON.stringify({ levels, coverage: top.extras?.MSFT_screencoverage ?? [] }));
