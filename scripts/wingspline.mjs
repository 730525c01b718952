#!/usr/bin/env node
// The package's command (`npx wingspline ...`). One command today:
//   wingspline grade [--out DIR] FILES_OR_FOLDERS...
// grades students' submission files against the lecturer's exercise files with the core
// (web/js/exercise/grade.js), and writes gradebook.csv, gradebook.md and gradebook-totals.csv.
// The exercise files come first: after the first submission, an exercise file is in the
// uploads, where a student could have put it, so it is a row of the gradebook and never an
// exercise. A folder is searched for .json files (an LMS's bulk download, unzipped).
// docs/exercises.md, "Handing in and grading", shows the whole flow.
//
// It runs from the package (node_modules/wingspline/scripts/wingspline.mjs) and from a built
// checkout alike: both have the site's modules in dist/.
import fs from 'node:fs';
import path from 'node:path';

const HELP = `Usage: wingspline grade [--out DIR] EXERCISES... SUBMISSIONS...

Grades Wingspline submission files against exercise files: every answer is checked
again by the core. Give the exercise files first, then the submissions; either may be
folders (searched for .json files, e.g. an assignment's downloaded submissions,
unzipped). An exercise file among the submissions is listed, never used. Writes
gradebook.csv, gradebook.md and gradebook-totals.csv (one row per submission file)
into DIR (default: the current folder).

  --out DIR    where to write the gradebook (created if missing)
  --help       this text
  --version    the Wingspline version
`;

const MAX_DEPTH = 6;
const MAX_FILES = 20000;

function fail(text, code = 2) {
  process.stderr.write(`wingspline: ${text}\n`);
  process.exit(code);
}

// Files named on the command line, folders searched for .json files (sorted, so the
// gradebook's order does not depend on the file system).
function collect(args) {
  const out = [];
  const walk = (dir, depth) => {
    if (depth > MAX_DEPTH) return;
    for (const entry of fs.readdirSync(dir, { withFileTypes: true }).sort((a, b) => a.name.localeCompare(b.name))) {
      const full = path.join(dir, entry.name);
      if (entry.isDirectory()) walk(full, depth + 1);
      else if (entry.isFile() && entry.name.toLowerCase().endsWith('.json')) out.push(full);
      if (out.length > MAX_FILES) fail(`more than ${MAX_FILES} .json files under ${dir}; name the folders that hold the submissions`);
    }
  };
  for (const arg of args) {
    let st;
    try {
      st = fs.statSync(arg);
    } catch {
      fail(`${arg}: no such file or folder`);
    }
    if (st.isDirectory()) walk(arg, 0);
    else out.push(arg);
  }
  return [...new Set(out)];
}

async function grade(args) {
  let outDir = '.';
  const inputs = [];
  for (let i = 0; i < args.length; i += 1) {
    if (args[i] === '--out') {
      if (i + 1 >= args.length) fail('--out needs a folder');
      outDir = args[i += 1];
    } else if (args[i].startsWith('--out=')) outDir = args[i].slice(6);
    else if (args[i] === '--') inputs.push(...args.slice(i + 1)), i = args.length;
    else if (args[i].startsWith('--')) fail(`unknown option ${args[i]} (see wingspline --help)`);
    else inputs.push(args[i]);
  }
  if (!inputs.length) fail(`grade needs the exercise files and the submission files\n\n${HELP}`);
  const names = collect(inputs);
  if (!names.length) fail('no .json file found in the folders given');

  const { loadWingspline } = await import('../dist/js/core/wingspline.js');
  const { gradeFiles, gradebookCsv, gradebookMarkdown, gradebookTotalsCsv, RESULTS } = await import('../dist/js/exercise/grade.js');
  const { GRADERS } = await import('../dist/js/exercise/graders.js');
  const { LESSON_OBJECTS } = await import('../dist/js/lessons/all.js');
  // Submitted code (the code kind) runs in the site's QuickJS sandbox, in this process; the
  // engine is loaded at the first function graded.
  const { createNodeSandbox } = await import('../dist/js/code/quickjs-node.js');
  const sandbox = createNodeSandbox();
  const api = await loadWingspline();
  const files = names.map((name) => ({ name, size: fs.statSync(name).size, read: () => fs.readFileSync(name, 'utf8') }));
  const { rows, exercises, problems } = await gradeFiles({ api, files, lessons: LESSON_OBJECTS, graders: GRADERS, run: (request) => sandbox.run(request) });
  for (const p of problems) process.stderr.write(`wingspline: ${p}\n`);
  if (!exercises.length) fail('no exercise file could be used: give the exercise files (format "wingspline-exercise") first, then the submissions', 1);

  fs.mkdirSync(outDir, { recursive: true });
  const csvPath = path.join(outDir, 'gradebook.csv');
  const mdPath = path.join(outDir, 'gradebook.md');
  fs.writeFileSync(csvPath, gradebookCsv(rows));
  fs.writeFileSync(mdPath, gradebookMarkdown(rows, { exercises, problems, app: api.version }));
  const totalsPath = path.join(outDir, 'gradebook-totals.csv');
  fs.writeFileSync(totalsPath, gradebookTotalsCsv(rows, exercises.length));
  const submissions = new Set(rows.map((r) => r.file)).size;
  const right = rows.filter((r) => r.result === RESULTS.right).length;
  process.stdout.write(`Graded ${submissions} submission file${submissions === 1 ? '' : 's'} against ${exercises.length} exercise${exercises.length === 1 ? '' : 's'}: ${right} of ${rows.length} answers right.\nWrote ${csvPath}, ${mdPath} and ${totalsPath}.\n`);
}

const [command, ...rest] = process.argv.slice(2);
if (!command || command === '--help' || command === '-h' || command === 'help') process.stdout.write(HELP);
else if (command === '--version') {
  const pkg = JSON.parse(fs.readFileSync(new URL('../package.json', import.meta.url), 'utf8'));
  process.stdout.write(`${pkg.version}\n`);
} else if (command === 'grade') {
  grade(rest).catch((err) => fail(`grading stopped: ${err?.stack ?? err}`, 1));
} else fail(`unknown command "${command}" (see wingspline --help)`);
