// Counts ez-tree's triangles per preset (for Sylva's gallery comparison; not shipped).
globalThis.document = { createElementNS: () => ({ addEventListener() {}, removeEventListener() {}, style: {}, setAttribute() {} }), createElement: () => ({ getContext: () => null, style: {} }) };
globalThis.self = globalThis;
globalThis.window = globalThis;
const { Tree } = await import('@dgreenheck/ez-tree');
const names = process.argv.slice(2);
for (const name of names) {
  for (const seed of [1, 2, 3]) {
    const tree = new Tree();
    tree.loadPreset(name);
    tree.options.seed = seed * 12345;
    tree.generate();
    let branchTris = 0, leafTris = 0, leaves = 0;
    tree.branchesMesh.geometry.index && (branchTris = tree.branchesMesh.geometry.index.count / 3);
    const lg = tree.leavesMesh.geometry;
    leafTris = lg.index ? lg.index.count / 3 : lg.attributes.position.count / 3;
    const box = { min: 1e9, max: -1e9 };
    const pos = tree.branchesMesh.geometry.attributes.position.array;
    for (let i = 1; i < pos.length; i += 3) { box.min = Math.min(box.min, pos[i]); box.max = Math.max(box.max, pos[i]); }
    console.log(JSON.stringify({ name, seed: tree.options.seed, branchTris, leafTris, total: branchTris + leafTris, height: +(box.max - box.min).toFixed(1) }));
  }
}
