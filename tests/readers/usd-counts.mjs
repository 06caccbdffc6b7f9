// Reads a Sylva .usda with tinyusdz (npm; its WASM build expects a browser, hence `window`,
// process.type and wasmBinary) and prints what it found as JSON: the render scene's meshes and
// tree/variant Xforms (tinyusdz's Tydra conversion), and from tinyusdz's own print of the
// parsed layer the PointInstancers with the lengths of their arrays. A root layer's subLayers
// are composed by tinyusdz first (composeSublayers, the tiles given to it as assets).
// usage: node usd-counts.mjs LAYER.usda
import { readFileSync } from "node:fs";
import path from "node:path";

import { fail, native } from "./tinyusdz-native.mjs";

const file = process.argv[2];
const bytes = new Uint8Array(readFileSync(file));

// The layer, composed when it names subLayers.
const layer = new native.TinyUSDZLoaderNative();
if (!layer.loadAsLayerFromBinary(bytes, file)) fail("cannot parse the layer", layer);
const sublayers = [];
const paths = layer.extractSublayerAssetPaths();
for (const p of Array.isArray(paths) ? paths : Array.from({ length: paths.size() }, (_, i) => paths.get(i))) sublayers.push(p);
if (sublayers.length) {
  layer.setBaseWorkingPath(path.dirname(file));
  for (const sub of sublayers)
    layer.setAsset(sub, new Uint8Array(readFileSync(path.join(path.dirname(file), sub))));
  if (!layer.composeSublayers()) fail("cannot compose the subLayers", layer);
}
const text = layer.layerToString();

// Array lengths from tinyusdz's print: top-level commas of `decl = [ ... ]`.
const arrayLength = (line) => {
  const body = line.slice(line.indexOf("= [") + 3, line.lastIndexOf("]"));
  if (!body.trim()) return 0;
  let depth = 0, n = 1;
  for (const c of body) {
    if (c === "(") depth++;
    else if (c === ")") depth--;
    else if (c === "," && depth === 0) n++;
  }
  return n;
};
const instancers = [];
let current = null;
for (const raw of text.split("\n")) {
  const line = raw.trim();
  const def = line.match(/^def PointInstancer "(\w+)"/);
  if (def) instancers.push((current = { name: def[1] }));
  if (!current) continue;
  for (const [key, decl] of [["ids", "int64[] ids"], ["protoIndices", "int[] protoIndices"],
                             ["positions", "point3f[] positions"],
                             ["orientations", "quath[] orientations"],
                             ["scales", "float3[] scales"], ["prototypes", "rel prototypes"]])
    if (line.startsWith(decl + " = ")) current[key] = arrayLength(line);
}

const out = {
  layers: 1 + sublayers.length,
  instancers: instancers.length,
  instances: instancers.reduce((s, i) => s + (i.protoIndices ?? 0), 0),
  ids: instancers.reduce((s, i) => s + (i.ids ?? 0), 0),
  prototypes: instancers.reduce((s, i) => s + (i.prototypes ?? 0), 0),
  mismatched: instancers.filter((i) => ["ids", "positions", "orientations", "scales"]
                                  .some((k) => i[k] !== i.protoIndices)).map((i) => i.name),
  trees: (text.match(/def Xform "tree_\d+"/g) ?? []).length,
  variantPrims: (text.match(/def Xform "variant_\d+"/g) ?? []).length,
  materials: (text.match(/def Material "/g) ?? []).length,
};

// The render scene tinyusdz makes of a single layer (Tydra): its meshes and nodes.
if (!sublayers.length) {
  const stage = new native.TinyUSDZLoaderNative();
  if (!stage.loadFromBinary(bytes, file)) fail("cannot convert the stage", stage);
  out.renderMeshes = stage.numMeshes();
  let xforms = 0;
  const walk = (n) => {
    if (/^tree_\d+$/.test(n.primName) && n.nodeType === "xform") xforms++;
    for (const c of n.children ?? []) walk(c);
  };
  walk(stage.getDefaultRootNode());
  out.renderTrees = xforms;
}
console.log(JSON.stringify(out));
