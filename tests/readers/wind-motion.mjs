// Loads a wind .glb (docs/wind.md) with three.js's GLTFLoader under Node, plays its "wind" clip
// with an AnimationMixer and prints, as JSON, how far the skinned mesh's highest vertex (a twig
// tip) and its lowest (the trunk's base ring) move over the clip, the clip's duration and the
// skin's joint count. Usage: node wind-motion.mjs FILE.glb
import { AnimationMixer, Vector3 } from 'three';
import { loadGltf } from './load-gltf.mjs';

const file = process.argv[2];
const gltf = await loadGltf(file);

const clip = gltf.animations.find((a) => a.name === 'wind');
if (!clip) throw new Error('no "wind" animation');
let skinned = null;
gltf.scene.traverse((o) => { if (o.isSkinnedMesh && !skinned) skinned = o; });
if (!skinned) throw new Error('no skinned mesh');
const pos = skinned.geometry.attributes.position;
let top = 0, bottom = 0;
for (let i = 0; i < pos.count; i++) {
  if (pos.getY(i) > pos.getY(top)) top = i;
  if (pos.getY(i) < pos.getY(bottom)) bottom = i;
}
const mixer = new AnimationMixer(gltf.scene);
mixer.clipAction(clip).play();
const rest = { top: new Vector3(), bottom: new Vector3() };
const moved = { top: 0, bottom: 0 };
const v = new Vector3();
for (let f = 0; f <= 60; f++) {
  mixer.setTime((clip.duration * f) / 60);
  gltf.scene.updateMatrixWorld(true);
  for (const [key, index] of [['top', top], ['bottom', bottom]]) {
    skinned.getVertexPosition(index, v);
    if (f === 0) rest[key].copy(v);
    moved[key] = Math.max(moved[key], v.distanceTo(rest[key]));
  }
}
console.log(JSON.stringify({ duration: clip.duration, tracks: clip.tracks.length,
  joints: skinned.skeleton.bones.length, tip: moved.top, base: moved.bottom }));
