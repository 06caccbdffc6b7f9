// Khronos glTF-Validator over one .glb/.gltf: prints the report's messages and exits 1 on any
// error. Usage: node validate.mjs FILE [--max-warnings N]
import fs from 'node:fs';
import path from 'node:path';
import validator from 'gltf-validator';

const file = process.argv[2];
if (!file) {
  console.error('usage: node validate.mjs FILE');
  process.exit(2);
}
const bytes = new Uint8Array(fs.readFileSync(file));
const report = await validator.validateBytes(bytes, {
  uri: path.basename(file),
  maxIssues: 200,
  externalResourceFunction: (uri) =>
    new Promise((resolve, reject) => {
      fs.readFile(path.join(path.dirname(file), decodeURIComponent(uri)), (err, data) =>
        err ? reject(err.toString()) : resolve(new Uint8Array(data)));
    }),
});
const issues = report.issues;
for (const m of issues.messages) {
  const severity = ['error', 'warning', 'info', 'hint'][m.severity] ?? m.severity;
  console.log(`${severity}: ${m.code} ${m.pointer ?? ''} ${m.message}`);
}
console.log(`${file}: ${issues.numErrors} errors, ${issues.numWarnings} warnings, ` +
            `${issues.numInfos} infos, ${issues.numHints} hints`);
process.exit(issues.numErrors === 0 ? 0 : 1);
