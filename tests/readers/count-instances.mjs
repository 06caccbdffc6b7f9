// Loads a .glb with three.js's GLTFLoader under Node (no DOM: textures are stubbed, geometry
// and the EXT_mesh_gpu_instancing nodes are read as a browser would) and prints, as JSON:
// instances (the summed InstancedMesh counts of the nodes that carry Sylva's ids), ids (the
// ids those nodes list), unique (mesh nodes of unique trees), meshes (geometry objects).
// Usage: node count-instances.mjs FILE.glb
import { loadGltf } from './load-gltf.mjs';

const file = process.argv[2];
const gltf = await loadGltf(file);

let instances = 0, ids = 0, unique = 0, meshes = 0, mismatched = 0;
gltf.scene.traverse((o) => {
  if (o.isMesh) meshes++;
  const extras = o.userData ?? {};
  if (Array.isArray(extras.sylva_ids)) {
    ids += extras.sylva_ids.length;
    const parts = o.isInstancedMesh ? [o] : o.children.filter((c) => c.isInstancedMesh);
    if (parts.length > 0) {
      instances += parts[0].count;
      if (parts.some((p) => p.count !== extras.sylva_ids.length)) mismatched++;
    }
  }
  if (extras.sylva_id !== undefined && (o.isMesh || o.children.some((c) => c.isMesh))) unique++;
});
console.log(JSON.stringify({ instances, ids, unique, meshes, mismatched }));
