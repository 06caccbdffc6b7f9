// Writes ez-tree presets as OBJ+MTL for a side-by-side render (comparison only; not shipped).
import fs from 'fs';
import path from 'path';
globalThis.document = { createElementNS: () => ({ addEventListener() {}, removeEventListener() {}, style: {}, setAttribute() {} }), createElement: () => ({ getContext: () => null, style: {} }) };
globalThis.self = globalThis; globalThis.window = globalThis;
const { Tree } = await import('@dgreenheck/ez-tree');
const assets = path.resolve('node_modules/@dgreenheck/ez-tree/src/lib/assets');
const [name, out, barkTex, leafTex] = process.argv.slice(2);
const tree = new Tree();
tree.loadPreset(name);
tree.options.seed = 12345;
tree.generate();
let text = `mtllib ${path.basename(out, '.obj')}.mtl\n`;
let base = 1;
for (const [mesh, mat] of [[tree.branchesMesh, 'bark'], [tree.leavesMesh, 'leaf']]) {
  mesh.updateMatrixWorld(true);
  const g = mesh.geometry.clone().applyMatrix4(mesh.matrixWorld);
  const p = g.attributes.position.array, uv = g.attributes.uv.array;
  const n = g.attributes.position.count;
  for (let i = 0; i < n; i++) text += `v ${p[3*i]} ${p[3*i+1]} ${p[3*i+2]}\n`;
  for (let i = 0; i < n; i++) text += `vt ${uv[2*i]} ${uv[2*i+1]}\n`;
  text += `usemtl ${mat}\n`;
  const idx = g.index ? g.index.array : [...Array(n).keys()];
  for (let i = 0; i < idx.length; i += 3)
    text += `f ${idx[i]+base}/${idx[i]+base} ${idx[i+1]+base}/${idx[i+1]+base} ${idx[i+2]+base}/${idx[i+2]+base}\n`;
  base += n;
}
fs.writeFileSync(out, text);
fs.writeFileSync(out.replace(/\.obj$/, '.mtl'),
  `newmtl bark\nKd 1 1 1\nmap_Kd ${assets}/bark/${barkTex}\nnewmtl leaf\nKd 1 1 1\nmap_Kd ${assets}/leaves/${leafTex}\nmap_d ${assets}/leaves/${leafTex}\n`);
console.log(out);
