// tinyusdz's WASM module (npm), loaded under Node: its build expects a browser, hence `window`,
// process.type and wasmBinary. Shared by the USD reader scripts.
import { readFileSync } from "node:fs";
import path from "node:path";
import { fileURLToPath } from "node:url";

globalThis.window = globalThis;
process.type = "renderer";
const dir = path.join(path.dirname(fileURLToPath(import.meta.url)), "node_modules", "tinyusdz");
const { default: init } = await import(path.join(dir, "tinyusdz.js"));
export const native = await init({ wasmBinary: readFileSync(path.join(dir, "tinyusdz.wasm")) });

// Prints tinyusdz's error for what failed and exits 1.
export const fail = (what, usd) => {
  console.error(`tinyusdz: ${what}: ${usd.error()}`);
  process.exit(1);
};
