// Khronos' glTF validator (npm gltf-validator) over every file given: prints each file's
// counts and messages; exits 1 if any has an error or a warning.
import validator from 'gltf-validator';
import fs from 'fs';

let bad = 0;
for (const file of process.argv.slice(2)) {
  const bytes = new Uint8Array(fs.readFileSync(file));
  const report = await validator.validateBytes(bytes, {
    maxIssues: 100,
    uri: file,
    externalResourceFunction: () => Promise.reject(new Error('no external resources expected')),
  });
  const i = report.issues;
  console.log(`gltf-validator ${report.validatorVersion}: ${file}: ${i.numErrors} errors, ${i.numWarnings} warnings, ` +
              `${i.numInfos} infos, ${i.numHints} hints`);
  for (const m of i.messages) console.log(`  ${m.severity} ${m.code} ${m.pointer ?? ''}: ${m.message}`);
  if (i.numErrors > 0 || i.numWarnings > 0) bad += 1;
}
process.exit(bad ? 1 : 0);
