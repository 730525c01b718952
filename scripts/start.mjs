// npm start: set up what is missing, build, serve dist/ and print the URL.
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
try {
  const { url } = await listen(createStaticServer(path.join(repoRoot, 'dist')), { port });
  log(`serving dist/ at ${url}  (Ctrl+C stops it)`);
} catch (err) {
  process.stderr.write(`[wingspline] cannot listen on port ${port}: ${err.message}\n` +
    '[wingspline] set another port, e.g. PORT=8081 npm start\n');
  process.exit(1);
}
