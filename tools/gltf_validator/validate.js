// The Khronos glTF-Validator (npm package gltf-validator, installed by tools/deps.sh --validator)
// over glTF / GLB files: one line per file with its error, warning and info counts and up to 5 of
// its error messages. Exit 0 when every file is valid (no error-severity issue), 1 when one is
// not, 2 when a file cannot be read or the validator is missing.
//   node tools/gltf_validator/validate.js FILE...
// NODE_PATH (set by tools/gltf-validate.sh) points at the installed package.
"use strict";
const fs = require("fs");
const path = require("path");

let validator;
try {
    validator = require("gltf-validator");
} catch (e) {
    console.error("gltf-validate: the npm package gltf-validator is not installed (tools/deps.sh --validator)");
    process.exit(2);
}

async function validate(file) {
    const bytes = fs.readFileSync(file);
    const report = await validator.validateBytes(new Uint8Array(bytes), {
        uri: path.basename(file),
        maxIssues: 100,
        externalResourceFunction: (uri) =>
            new Promise((resolve, reject) => {
                fs.readFile(path.resolve(path.dirname(file), decodeURIComponent(uri)), (err, data) =>
                    err ? reject(err.toString()) : resolve(new Uint8Array(data)));
            }),
    });
    const issues = report.issues;
    const errors = issues.messages.filter((m) => m.severity === 0).slice(0, 5)
        .map((m) => `${m.code} at ${m.pointer || "-"}: ${m.message}`);
    console.log(`${file}: ${issues.numErrors} errors, ${issues.numWarnings} warnings, ${issues.numInfos} infos` +
                (errors.length ? "\n  " + errors.join("\n  ") : ""));
    return issues.numErrors === 0;
}

(async () => {
    const files = process.argv.slice(2);
    if (files.length === 0) {
        console.error("usage: node tools/gltf_validator/validate.js FILE...");
        process.exit(2);
    }
    let allValid = true;
    for (const f of files) {
        try {
            allValid = (await validate(f)) && allValid;
        } catch (e) {
            console.error(`${f}: cannot be validated: ${e}`);
            process.exit(2);
        }
    }
    process.exit(allValid ? 0 : 1);
})();
