// Runs the Khronos glTF validator (npm package gltf-validator) on each file given and prints one
// summary line per file; exit status 1 if any file has validator errors.
//   node scenes/validate_gltf.js [--verbose] FILE.gltf ...
// NODE_PATH must let require('gltf-validator') resolve (scenes/validate_scenes.sh sets it).
'use strict';
const fs = require('fs');
const path = require('path');
const validator = require('gltf-validator');

async function validate(file, verbose) {
  const data = new Uint8Array(fs.readFileSync(file));
  const report = await validator.validateBytes(data, {
    uri: path.basename(file),
    maxIssues: 0,
    externalResourceFunction: (uri) =>
      new Promise((resolve, reject) => {
        fs.readFile(path.join(path.dirname(file), decodeURIComponent(uri)), (err, bytes) =>
          err ? reject(err.toString()) : resolve(new Uint8Array(bytes)));
      }),
  });
  const i = report.issues;
  console.log(`${file}: ${i.numErrors} errors, ${i.numWarnings} warnings, ${i.numInfos} infos, ${i.numHints} hints`);
  for (const m of i.messages) {
    if (m.severity === 0 || (verbose && m.severity <= 1)) {
      console.log(`  [${['error', 'warning', 'info', 'hint'][m.severity]}] ${m.code} ${m.pointer || ''}: ${m.message}`);
    }
  }
  return i.numErrors;
}

(async () => {
  const args = process.argv.slice(2);
  const verbose = args.includes('--verbose');
  let errors = 0;
  for (const f of args.filter((a) => a !== '--verbose')) {
    try {
      errors += await validate(f, verbose);
    } catch (e) {
      console.log(`${f}: validator failed: ${e}`);
      errors += 1;
    }
  }
  process.exit(errors > 0 ? 1 : 0);
})();
