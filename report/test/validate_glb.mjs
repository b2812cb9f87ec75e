// Validates glTF binaries with the Khronos glTF validator (gltf-validator, pinned in
// package.json): fails on any error or warning.
//   node test/validate_glb.mjs FILE.glb...
import validator from 'gltf-validator';
import { readFileSync } from 'node:fs';

let passed = 0, failed = 0;
for (const file of process.argv.slice(2)) {
  const report = await validator.validateBytes(new Uint8Array(readFileSync(file)));
  const { numErrors, numWarnings } = report.issues;
  const ok = numErrors === 0 && numWarnings === 0;
  if (ok) passed++; else failed++;
  console.log(`${ok ? 'ok  ' : 'FAIL'} ${file}: ${numErrors} errors, ${numWarnings} warnings (Khronos glTF validator ${report.validatorVersion})`);
  for (const m of report.issues.messages) console.log(`     ${m.code}: ${m.message} ${m.pointer || ''}`);
}
console.log(`${passed} passed, ${failed} failed`);
process.exit(failed ? 1 : 0);
