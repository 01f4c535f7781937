// Khronos' glTF-Validator (npm package gltf-validator) on one file: prints the issue counts and every
// error or warning, exits 1 on any error, 77 (skipped) when the package is not installed.
const fs = require('fs');
const path = require('path');
let validator;
try {
  validator = require('gltf-validator');
} catch (e) {
  console.log('skipped: the npm package gltf-validator is not installed (npm install -g gltf-validator)');
  process.exit(77);
}
const file = process.argv[2];
validator.validateBytes(new Uint8Array(fs.readFileSync(file)), {
  uri: path.basename(file),
  maxIssues: 0,
  externalResourceFunction: () => Promise.reject(new Error('no external resources')),
}).then((report) => {
  const i = report.issues;
  console.log(`${file}: ${i.numErrors} errors, ${i.numWarnings} warnings, ${i.numInfos} infos, ${i.numHints} hints`);
  const seen = {};
  for (const m of i.messages) {  // the first of each kind of error or warning, and how many
    if (m.severity > 1) continue;
    seen[m.code] = (seen[m.code] || 0) + 1;
    if (seen[m.code] === 1) console.log(`  ${m.severity === 0 ? 'error' : 'warning'} ${m.code} ${m.pointer || ''}: ${m.message}`);
  }
  for (const code in seen) console.log(`  ${code}: ${seen[code]}`);
  process.exit(i.numErrors === 0 ? 0 : 1);
}, (error) => {
  console.log(`${file}: validator failed: ${error}`);
  process.exit(1);
});
