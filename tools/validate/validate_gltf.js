// Runs the Khronos glTF validator (npm `gltf-validator`) on every .gltf/.glb file given or
// found under the directories given, prints one line per file (errors, warnings, infos,
// hints) and every issue at warning level or above, and exits 1 when any file has an
// error or a warning that is not listed in ACCEPTED below.
'use strict';
const fs = require('fs');
const path = require('path');
const validator = require('gltf-validator');

// Warnings we accept, with the reason. Empty: every warning fails the run.
const ACCEPTED = {};

function collect(p, out) {
  const st = fs.statSync(p);
  if (st.isDirectory()) {
    for (const e of fs.readdirSync(p).sort()) collect(path.join(p, e), out);
  } else if (/\.(gltf|glb)$/i.test(p)) {
    out.push(p);
  }
}

async function main() {
  const files = [];
  for (const a of process.argv.slice(2)) collect(a, files);
  if (files.length === 0) {
    console.error('validate_gltf: no .gltf or .glb files found in ' + process.argv.slice(2).join(' '));
    process.exit(1);
  }
  let failed = 0;
  for (const f of files) {
    const report = await validator.validateBytes(new Uint8Array(fs.readFileSync(f)), {
      uri: f,
      maxIssues: 0,
    });
    const i = report.issues;
    const bad = i.messages.filter((m) => m.severity === 0 || (m.severity === 1 && !(m.code in ACCEPTED)));
    console.log(`${bad.length ? 'FAIL' : 'ok  '} ${f}: ${i.numErrors} errors, ${i.numWarnings} warnings, ${i.numInfos} infos, ${i.numHints} hints`);
    for (const m of i.messages.filter((m) => m.severity <= 1)) {
      console.log(`       ${['error', 'warning'][m.severity]} ${m.code} ${m.pointer || ''}: ${m.message}`);
    }
    if (bad.length) failed++;
  }
  console.log(`Khronos glTF validator ${validator.version()}`);
  console.log(`gltf-validator: ${files.length - failed} passed, ${failed} failed`);
  process.exit(failed ? 1 : 0);
}

main().catch((e) => {
  console.error('validate_gltf: ' + e);
  process.exit(1);
});
