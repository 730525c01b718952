// Installs what is missing, and only that:
//  * Debian packages through apt (as root, or through sudo when it needs no password);
//    otherwise prints the exact command to run and stops.
//  * npm packages (playwright-core ...) when node_modules does not match package-lock.json.
import fs from 'node:fs';
import path from 'node:path';
import { pathToFileURL } from 'node:url';
import { repoRoot, log, run, quiet } from './lib/run.mjs';

// Why each package: the build and tests need exactly these (README "Dependencies").
export const debianPackages = [
  ['cmake', 'configures the native and wasm builds'],
  ['g++', 'compiles the native core and tests'],
  ['emscripten', 'compiles the core to WebAssembly (3.1.6)'],
  ['libglm-dev', 'vector maths in the core'],
  ['catch2', 'native unit tests (v2)'],
  ['chromium', 'browser tests, headless, driven by playwright-core'],
  ['clang-14', 'libFuzzer targets for the parsers and evaluators'],
  ['libclang-rt-14-dev', 'the fuzzer and sanitizer runtimes for clang-14'],
];

function isInstalled(pkg) {
  const r = quiet('dpkg-query', ['-W', '-f=${Status}', pkg]);
  return r.code === 0 && r.stdout.includes('install ok installed');
}

async function installDebianPackages(missing) {
  const aptArgs = ['-o', 'DPkg::Lock::Timeout=600', 'install', '-y', '--no-install-recommends', ...missing];
  const printable = `sudo apt-get update && sudo apt-get ${aptArgs.join(' ')}`;
  let prefix = [];
  if (typeof process.getuid === 'function' && process.getuid() !== 0) {
    if (quiet('sudo', ['-n', 'true']).code !== 0) {
      process.stderr.write(
        `\n[wingspline] These Debian packages are missing: ${missing.join(', ')}\n` +
        `[wingspline] You are not root and sudo needs a password, so nothing was installed.\n` +
        `[wingspline] Ask an administrator (or use a root shell) to run:\n\n    ${printable}\n\n` +
        `[wingspline] then run this npm command again.\n`);
      process.exit(1);
    }
    prefix = ['sudo', '-n'];
  }
  const env = { ...process.env, DEBIAN_FRONTEND: 'noninteractive' };
  const exec = (args) => prefix.length
    ? run(prefix[0], [...prefix.slice(1), 'apt-get', ...args], { env })
    : run('apt-get', args, { env });
  log(`installing Debian packages: ${missing.join(' ')}`);
  let code = await exec(aptArgs);
  if (code !== 0) {
    // A fresh machine may have empty package lists; refresh them once and retry.
    log('apt-get install failed; refreshing the package lists and trying once more');
    await exec(['-o', 'DPkg::Lock::Timeout=600', 'update']);
    code = await exec(aptArgs);
  }
  if (code !== 0) {
    process.stderr.write(`[wingspline] apt-get could not install ${missing.join(' ')}; see the messages above.\n`);
    process.exit(1);
  }
}

function npmPackagesCurrent() {
  const lock = path.join(repoRoot, 'package-lock.json');
  const installed = path.join(repoRoot, 'node_modules', '.package-lock.json');
  if (!fs.existsSync(installed)) return false;
  if (fs.existsSync(lock) && fs.statSync(lock).mtimeMs > fs.statSync(installed).mtimeMs) return false;
  const pkg = JSON.parse(fs.readFileSync(path.join(repoRoot, 'package.json'), 'utf8'));
  return [...Object.keys(pkg.dependencies ?? {}), ...Object.keys(pkg.devDependencies ?? {})].every((name) =>
    fs.existsSync(path.join(repoRoot, 'node_modules', name, 'package.json')));
}

export async function setup() {
  const missing = debianPackages.map(([name]) => name).filter((name) => !isInstalled(name));
  if (missing.length > 0) await installDebianPackages(missing);
  if (!npmPackagesCurrent()) {
    log('installing npm packages (npm ci)');
    const code = await run('npm', ['ci', '--no-audit', '--no-fund']);
    if (code !== 0) {
      process.stderr.write('[wingspline] npm ci failed; see the messages above.\n');
      process.exit(1);
    }
  }
}

if (process.argv[1] && import.meta.url === pathToFileURL(process.argv[1]).href) {
  await setup();
  log('setup complete: every Debian and npm package is present');
}
