// Reads a Sylva LOD chain stage (<species>_lods.usda) with tinyusdz and prints, as JSON, its
// variant set "lod" and what each variant composes to: the default selection as written, every
// other one selected in the layer's `variants` metadata (as a stronger layer would), then
// tinyusdz's composeVariants and its render scene (Tydra): the meshes, their triangles and the
// material each is bound to (its colour and normal maps).
// usage: node usd-lods.mjs SPECIES_lods.usda
import { readFileSync } from "node:fs";

import { fail, native } from "./tinyusdz-native.mjs";

const file = process.argv[2];
const text = readFileSync(file, "utf8");

// The layer as tinyusdz parsed it: the variant set's declaration, selection and variants.
const layer = new native.TinyUSDZLoaderNative();
if (!layer.loadAsLayerFromBinary(new Uint8Array(Buffer.from(text)), file)) fail("cannot parse", layer);
const printed = layer.layerToString();
const declared = /prepend variantSets = \["lod"\]/.test(printed);
const selection = (printed.match(/string lod = "(\w+)"/) ?? [])[1] ?? null;
const body = printed.slice(printed.indexOf('variantSet "lod" = {'));
const variants = [...body.matchAll(/^ {8}"(\w+)" \{$/gm)].map((m) => m[1]);

const out = { declared, selection, variants: {} };
for (const v of variants) {
  const selected = text.replace(/string lod = "\w+"/, `string lod = "${v}"`);
  const usd = new native.TinyUSDZLoaderNative();
  if (!usd.loadAsLayerFromBinary(new Uint8Array(Buffer.from(selected)), file)) fail(v, usd);
  if (!usd.composeVariants()) fail(`composeVariants (${v})`, usd);
  const composed = usd.layerToString();
  if (!usd.layerToRenderScene()) fail(`render scene (${v})`, usd);
  const meshes = [];
  for (let i = 0; i < usd.numMeshes(); ++i) {
    const m = usd.getMesh(i);
    const n = m.faceVertexIndices?.length ?? 0;
    // The bound material's colour and normal textures, as files.
    const uri = (id) => (id >= 0 ? usd.getImage(usd.getTexture(id).textureImageId).uri : null);
    const mat = m.materialId >= 0 ? usd.getMaterial(m.materialId) : null;
    meshes.push({ path: m.absPath, triangles: n / 3, materialId: m.materialId,
                  color: mat ? uri(mat.diffuseColorTextureId) : null,
                  normal: mat ? uri(mat.normalTextureId) : null });
  }
  out.variants[v] = {
    meshes: meshes.length,
    triangles: meshes.reduce((s, m) => s + m.triangles, 0),
    paths: meshes.map((m) => m.path),
    bound: meshes.filter((m) => m.materialId >= 0).length,
    colorMaps: meshes.map((m) => m.color),
    normalMaps: meshes.map((m) => m.normal),
    // After composition no variant set is left, and only this variant's Xform is there.
    composedVariantSets: (composed.match(/variantSet "/g) ?? []).length,
    otherLevels: variants.filter((w) => w !== v && composed.includes(`def Xform "${w}"`)),
  };
}
console.log(JSON.stringify(out));
