// Times ez-tree's generator per tree, warm, in this process (for issue #41's side-by-side with
// Sylva's oak; not shipped): node time.mjs "Oak Large" [trees]
// Prints per tree the CPU milliseconds (process.cpuUsage, user + system) and the triangles, then
// the median over the trees after three warm-up trees.
globalThis.document = { createElementNS: () => ({ addEventListener() {}, removeEventListener() {}, style: {}, setAttribute() {} }), createElement: () => ({ getContext: () => null, style: {} }) };
globalThis.self = globalThis;
globalThis.window = globalThis;
const { Tree } = await import('@dgreenheck/ez-tree');
const name = process.argv[2] || 'Oak Large';
const count = Number(process.argv[3] || 12);
const ms = [], tris = [];
for (let i = 0; i < count + 3; ++i) {
  const tree = new Tree();
  tree.loadPreset(name);
  tree.options.seed = 1000 + i;
  const t0 = process.cpuUsage();
  tree.generate();
  const dt = process.cpuUsage(t0);
  const b = tree.branchesMesh.geometry, l = tree.leavesMesh.geometry;
  const n = (b.index ? b.index.count : b.attributes.position.count) / 3 +
            (l.index ? l.index.count : l.attributes.position.count) / 3;
  if (i >= 3) { ms.push((dt.user + dt.system) / 1000); tris.push(n); }
}
const median = (a) => [...a].sort((x, y) => x - y)[Math.floor(a.length / 2)];
console.log(JSON.stringify({ name, trees: ms.length, median_cpu_ms: median(ms), min_cpu_ms: Math.min(...ms), median_triangles: median(tris),
  triangles_per_second: median(tris) / (median(ms) / 1000) }));
