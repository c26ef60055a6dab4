// The Khronos glTF Validator (npm's gltf-validator) on one file:
//   NODE_PATH=$(npm root -g) node scripts/gltf_validate.js city.glb
// Prints "gltf_validate: E errors, W warnings, I infos" and each error's code and pointer, one a line;
// exits 0 with no errors, 1 with errors, 2 when the validator cannot run (the module is missing).
const fs = require("fs");
const path = require("path");
let validator;
try {
  validator = require("gltf-validator");
} catch (e) {
  console.log("gltf_validate: the gltf-validator module is not installed (npm install -g gltf-validator)");
  process.exit(2);
}
const file = process.argv[2];
validator
  .validateBytes(new Uint8Array(fs.readFileSync(file)), {
    uri: path.basename(file),
    maxIssues: 0,
    externalResourceFunction: (uri) => Promise.reject(new Error("external resource " + uri)),
  })
  .then((report) => {
    const i = report.issues;
    console.log(`gltf_validate: ${i.numErrors} errors, ${i.numWarnings} warnings, ${i.numInfos} infos`);
    for (const m of i.messages) if (m.severity === 0) console.log(`  ${m.code} ${m.pointer || ""}: ${m.message}`);
    process.exit(i.numErrors === 0 ? 0 : 1);
  })
  .catch((e) => {
    console.log("gltf_validate: " + e);
    process.exit(1);
  });
