// npm start: set up what is missing, build, serve dist/ and print the folder and the URL(s).
// HOST (default 127.0.0.1) and PORT (default 8080) choose where it listens.
import os from 'node:os';
import path from 'node:path';
import { setup } from './setup.mjs';
import { build } from './build.mjs';
import { repoRoot, log } from './lib/run.mjs';
import { createStaticServer, listen } from './lib/static-server.mjs';

try {
  await setup();
  await build();
} catch (err) {
  process.stderr.write(`[wingspline] ${err.message}\n`);
  process.exit(1);
}

const port = Number.parseInt(process.env.PORT ?? '8080', 10);
if (!Number.isInteger(port) || port < 0 || port > 65535) {
  process.stderr.write(`[wingspline] PORT must be a number from 0 to 65535, not '${process.env.PORT}'\n`);
  process.exit(1);
}
// HOST: the address to listen on. The default, 127.0.0.1, serves this machine only; a
// classroom sets HOST=0.0.0.0 (every interface) or one of the machine's addresses.
const host = process.env.HOST || '127.0.0.1';
const folder = path.join(repoRoot, 'dist');
let url;
try {
  ({ url } = await listen(createStaticServer(folder), { host, port }));
} catch (err) {
  process.stderr.write(`[wingspline] cannot listen on HOST ${host} port ${port}: ${err.message}\n` +
    '[wingspline] set another port, e.g. PORT=8081 npm start, or HOST to an address of this machine ' +
    '(HOST=0.0.0.0 listens on all of them)\n');
  process.exit(1);
}
log(`serving ${folder}`);
for (const address of addressesServed(host, new URL(url).port)) log(`  at ${address}`);
log('(Ctrl+C stops it)');

// The URLs that reach the server: for a wildcard host (0.0.0.0, ::) one per IPv4 address of
// this machine, loopback included; otherwise the one URL listen() gives.
function addressesServed(listenHost, actualPort) {
  if (listenHost !== '0.0.0.0' && listenHost !== '::') return [url];
  return Object.values(os.networkInterfaces()).flat()
    .filter((a) => a.family === 'IPv4' || a.family === 4)
    .map((a) => `http://${a.address}:${actualPort}/`);
}
