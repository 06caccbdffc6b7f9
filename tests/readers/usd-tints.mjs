// Reads a Sylva .usda with tinyusdz and prints, as JSON, the meshes that carry
// primvars:displayColor (the leaf tints) as tinyusdz parsed them: the mesh, the number of
// colours, their interpolation and the number of faces. usage: node usd-tints.mjs LAYER.usda
import { readFileSync } from "node:fs";

import { fail, native } from "./tinyusdz-native.mjs";

const file = process.argv[2];
const layer = new native.TinyUSDZLoaderNative();
if (!layer.loadAsLayerFromBinary(new Uint8Array(readFileSync(file)), file))
  fail("cannot parse the layer", layer);
const text = layer.layerToString();
const count = (line) => {
  const body = line.slice(line.indexOf("= [") + 3, line.lastIndexOf("]"));
  let depth = 0, n = body.trim() ? 1 : 0;
  for (const c of body) {
    if (c === "(") depth++;
    else if (c === ")") depth--;
    else if (c === "," && depth === 0) n++;
  }
  return n;
};
const meshes = [];
let mesh = null;
const lines = text.split("\n");
for (let i = 0; i < lines.length; i++) {
  const line = lines[i].trim();
  const def = line.match(/^def Mesh "(\w+)"/);
  if (def) meshes.push((mesh = { name: def[1] }));
  if (!mesh) continue;
  if (line.startsWith("int[] faceVertexCounts")) mesh.faces = count(line);
  if (line.includes("primvars:displayColor")) {
    mesh.colors = count(line);
    const interp = lines.slice(i, i + 4).join(" ").match(/interpolation = "(\w+)"/);
    mesh.interpolation = interp ? interp[1] : null;
  }
}
console.log(JSON.stringify({ meshes: meshes.filter((m) => m.colors !== undefined), all: meshes.length }));
