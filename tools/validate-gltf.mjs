#!/usr/bin/env node
// Runs the Khronos glTF validator (pinned in tools/node) on one .gltf or .glb file.
// Exit status: 0 no errors, 1 the report has errors, 2 usage, IO or setup problems.
import { createRequire } from 'node:module';
import { readFile } from 'node:fs/promises';
import path from 'node:path';

const usage = 'usage: node tools/validate-gltf.mjs FILE.gltf|FILE.glb';
const severityNames = ['error', 'warning', 'info', 'hint'];

function fail(message) {
  console.error(`validate-gltf: ${message}`);
  process.exit(2);
}

// The package lives in tools/node/node_modules, which plain ESM resolution from tools/ would not search.
function loadValidator() {
  const requireFromTools = createRequire(new URL('./node/package.json', import.meta.url));
  try {
    return requireFromTools('gltf-validator');
  } catch (err) {
    fail(`cannot load gltf-validator (run tools/install-deps.sh): ${err.message}`);
  }
}

async function main() {
  const args = process.argv.slice(2);
  if (args.length !== 1 || args[0].startsWith('-')) fail(usage);
  const file = path.resolve(args[0]);
  const validator = loadValidator();

  let bytes;
  try {
    bytes = new Uint8Array(await readFile(file));
  } catch (err) {
    fail(`cannot read ${file}: ${err.message}`);
  }

  // Buffers and images referenced by relative URI are read beside the model, so split assets are checked too.
  const externalResourceFunction = async (uri) =>
    new Uint8Array(await readFile(path.resolve(path.dirname(file), decodeURIComponent(uri))));

  let report;
  try {
    report = await validator.validateBytes(bytes, {
      uri: path.basename(file),
      maxIssues: 0,
      writeTimestamp: false,
      externalResourceFunction,
    });
  } catch (err) {
    // A rejection means the validator could not even recognise the input as glTF or GLB.
    fail(`cannot validate ${file}: ${err}`);
  }

  const issues = report.issues;
  console.log(`${file}: ${issues.numErrors} errors, ${issues.numWarnings} warnings, ` +
              `${issues.numInfos} infos, ${issues.numHints} hints (gltf-validator ${validator.version()})`);
  for (const m of issues.messages) {
    const where = m.pointer ? ` at ${m.pointer}` : (m.offset !== undefined ? ` at byte ${m.offset}` : '');
    console.log(`  ${severityNames[m.severity] ?? m.severity} ${m.code}${where}: ${m.message}`);
  }
  process.exit(issues.numErrors > 0 ? 1 : 0);
}

main().catch((err) => fail(String(err && err.stack ? err.stack : err)));
