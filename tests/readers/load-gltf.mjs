// A .glb read by three.js's GLTFLoader under Node, as a browser reads it but for the images:
// they need a DOM or createImageBitmap to decode, so every texture is an empty one. Shared by
// the three.js reader scripts.
import fs from 'node:fs';
import { Texture } from 'three';
import { GLTFLoader } from 'three/examples/jsm/loaders/GLTFLoader.js';

export async function loadGltf(file) {
  const data = fs.readFileSync(file);
  const buffer = data.buffer.slice(data.byteOffset, data.byteOffset + data.byteLength);
  const loader = new GLTFLoader();
  loader.register(() => ({ name: 'sylva_stub_textures', loadTexture: async () => new Texture() }));
  return new Promise((resolve, reject) => loader.parse(buffer, '', resolve, reject));
}
