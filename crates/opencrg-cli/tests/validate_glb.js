// Validates .glb files with the Khronos glTF validator (npm package gltf-validator):
// exits 1 when a file has an error or a warning. Run by test.sh.
//   node validate_glb.js FILE.glb...   (with gltf-validator in NODE_PATH)
const validator = require('gltf-validator');
const fs = require('fs');

(async () => {
    let failed = false;
    for (const file of process.argv.slice(2)) {
        const report = await validator.validateBytes(new Uint8Array(fs.readFileSync(file)));
        const { numErrors, numWarnings } = report.issues;
        console.log(`${file}: ${numErrors} errors, ${numWarnings} warnings (Khronos glTF validator ${report.validatorVersion})`);
        for (const m of report.issues.messages.filter((m) => m.severity <= 1)) {
            console.log(`  ${m.code} ${m.pointer || ''}: ${m.message}`);
        }
        failed = failed || numErrors > 0 || numWarnings > 0;
    }
    process.exit(failed ? 1 : 0);
})();
