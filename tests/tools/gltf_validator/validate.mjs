// Khronos glTF-Validator harness for the ArtiMo tests.
//
// Install (once; node_modules is git-ignored):
//     npm install --prefix tests/tools/gltf_validator --no-audit --no-fund
// Use:
//     node tests/tools/gltf_validator/validate.mjs FILE.glb [FILE.gltf ...]
// Prints one JSON object per input file, one per line:
//     {"path", "ok", "validatorVersion", "numErrors", "numWarnings", "numInfos", "numHints",
//      "truncated", "messages": [{"code", "message", "severity", "pointer"}]}
// ("ok" is false when the file could not be read or parsed at all; "error" then says why.)
// Severity: 0 error, 1 warning, 2 info, 3 hint. Exit status: 0 when every file has no
// errors and no warnings, 1 otherwise, 2 on a usage error.

import { readFile } from "node:fs/promises";
import path from "node:path";
import validator from "gltf-validator";

const MAX_ISSUES = 200;

async function externalResource(baseDir, uri) {
  const target = path.resolve(baseDir, decodeURIComponent(uri));
  return new Uint8Array(await readFile(target));
}

async function validateFile(file) {
  const result = { path: file, ok: false, validatorVersion: validator.version() };
  try {
    const data = new Uint8Array(await readFile(file));
    const report = await validator.validateBytes(data, {
      uri: path.basename(file),
      maxIssues: MAX_ISSUES,
      externalResourceFunction: (uri) => externalResource(path.dirname(file), uri),
    });
    const issues = report.issues;
    Object.assign(result, {
      ok: true,
      numErrors: issues.numErrors,
      numWarnings: issues.numWarnings,
      numInfos: issues.numInfos,
      numHints: issues.numHints,
      truncated: Boolean(issues.truncated),
      messages: issues.messages.map((m) => ({
        code: m.code,
        message: m.message,
        severity: m.severity,
        pointer: m.pointer ?? null,
      })),
    });
  } catch (error) {
    result.error = String(error && error.message ? error.message : error);
  }
  return result;
}

const files = process.argv.slice(2);
if (files.length === 0) {
  console.error("usage: node validate.mjs FILE.glb [FILE ...]");
  process.exit(2);
}
let clean = true;
for (const file of files) {
  const result = await validateFile(file);
  clean = clean && result.ok && result.numErrors === 0 && result.numWarnings === 0;
  process.stdout.write(JSON.stringify(result) + "\n");
}
process.exit(clean ? 0 : 1);
