#!/usr/bin/env node
// Validates glTF / GLB files with the Khronos glTF-Validator (npm package
// "gltf-validator", a JS library exposing validateBytes).
//
// usage: node scripts/validate-gltf.mjs [--tools DIR] [--werror] [--json] [-v] FILE...
//   --tools DIR  directory whose node_modules/ holds gltf-validator
//                (default: $RRC_TOOLS_DIR or build/tools)
//   --werror     treat warnings as errors
//   --json       print the full report of every file as JSON
//   -v           print every issue (default: errors and warnings only)
// Exit status: 0 if no file has errors (and no warnings with --werror),
// 1 otherwise, 2 on usage / setup problems.
//
// External resources (buffers/images referenced by relative URI) are loaded
// only from inside the asset's own directory; anything resolving outside it
// (absolute paths, ../ escapes) is refused and reported as an IO error.

import { createRequire } from 'node:module';
import fs from 'node:fs';
import path from 'node:path';

const args = process.argv.slice(2);
let toolsDir = process.env.RRC_TOOLS_DIR || 'build/tools';
let werror = false;
let json = false;
let verbose = false;
const files = [];
for (let i = 0; i < args.length; i++) {
  const a = args[i];
  if (a === '--tools') toolsDir = args[++i];
  else if (a === '--werror') werror = true;
  else if (a === '--json') json = true;
  else if (a === '-v' || a === '--verbose') verbose = true;
  else if (a === '-h' || a === '--help') {
    console.log('usage: validate-gltf.mjs [--tools DIR] [--werror] [--json] [-v] FILE...');
    process.exit(0);
  } else files.push(a);
}
if (files.length === 0) {
  console.error('validate-gltf: no input files');
  process.exit(2);
}

let validator;
try {
  const require = createRequire(path.join(path.resolve(toolsDir), 'node_modules', 'noop.js'));
  validator = require('gltf-validator');
} catch (e) {
  console.error(`validate-gltf: cannot load gltf-validator from ${toolsDir}/node_modules: ${e.message}`);
  process.exit(2);
}

const SEVERITY = ['error', 'warning', 'info', 'hint'];

function loader(assetPath) {
  const dir = path.dirname(path.resolve(assetPath));
  return (uri) => new Promise((resolve, reject) => {
    let rel;
    try {
      rel = decodeURIComponent(uri);
    } catch (e) {
      reject(`bad URI encoding: ${uri}`);
      return;
    }
    if (/^[a-zA-Z][a-zA-Z0-9+.-]*:/.test(rel)) {
      reject(`refusing to load '${uri}': URIs with a scheme are not loaded`);
      return;
    }
    const full = path.resolve(dir, rel);
    if (path.isAbsolute(rel) || !(full === dir || full.startsWith(dir + path.sep))) {
      reject(`refusing to load '${uri}': resolves outside the asset directory`);
      return;
    }
    fs.readFile(full, (err, data) => (err ? reject(err.toString()) : resolve(new Uint8Array(data))));
  });
}

let failed = false;
for (const file of files) {
  let bytes;
  try {
    bytes = new Uint8Array(fs.readFileSync(file));
  } catch (e) {
    console.log(`${file}: cannot read: ${e.message}`);
    failed = true;
    continue;
  }
  let report;
  try {
    report = await validator.validateBytes(bytes, {
      uri: path.basename(file),
      maxIssues: 0,
      writeTimestamp: false,
      externalResourceFunction: loader(file),
    });
  } catch (e) {
    // rejection: arguments invalid or format could not be detected
    console.log(`${file}: errors 1, warnings 0, infos 0, hints 0  FAIL`);
    console.log(`  error   FORMAT  ${e}`);
    failed = true;
    continue;
  }
  const is = report.issues;
  const bad = is.numErrors > 0 || (werror && is.numWarnings > 0);
  if (bad) failed = true;
  const info = report.info || {};
  const extra = [];
  if (info.totalTriangleCount !== undefined) extra.push(`triangles ${info.totalTriangleCount} (each mesh counted once)`);
  if (info.animationCount !== undefined) extra.push(`animations ${info.animationCount}`);
  if (info.maxInfluences !== undefined) extra.push(`maxInfluences ${info.maxInfluences}`);
  console.log(`${file}: errors ${is.numErrors}, warnings ${is.numWarnings}, infos ${is.numInfos}, ` +
              `hints ${is.numHints}  ${bad ? 'FAIL' : 'OK'}` + (extra.length ? `  (${extra.join(', ')})` : ''));
  for (const m of is.messages) {
    if (!verbose && m.severity > 1) continue;
    console.log(`  ${SEVERITY[m.severity].padEnd(7)} ${m.code}  ${m.pointer || m.offset || ''}  ${m.message}`);
  }
  if (json) console.log(JSON.stringify(report, null, 2));
}
process.exit(failed ? 1 : 0);
