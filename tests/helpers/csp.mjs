// The Content Security Policy every page must carry, as a checker shared by the
// source test (tests/wasm/security/source.test.mjs) and the browser test
// (tests/browser/security/csp.test.mjs): scripts only from the site ('self'), WebAssembly
// compilation allowed ('wasm-unsafe-eval', which permits nothing else), no
// 'unsafe-inline', no 'unsafe-eval', no remote origin anywhere, no plugins, no <base>.

// Parses "default-src 'self'; script-src ..." into { directive: [sources] }.
export function parseCsp(content) {
  const out = {};
  for (const part of content.split(';')) {
    const [name, ...sources] = part.trim().split(/\s+/);
    if (name) out[name.toLowerCase()] = sources;
  }
  return out;
}

// The rules every page's policy must satisfy; returns the broken ones as sentences.
export function cspProblems(content) {
  const csp = parseCsp(content ?? '');
  const problems = [];
  const self = ["'self'"];
  if (!csp['default-src'] || csp['default-src'].join(' ') !== "'self'") problems.push("default-src must be exactly 'self'");
  const scripts = csp['script-src'] ?? csp['default-src'] ?? [];
  const allowed = new Set([...self, "'wasm-unsafe-eval'"]);
  for (const s of scripts) if (!allowed.has(s)) problems.push(`script-src allows ${s}`);
  for (const [name, sources] of Object.entries(csp)) {
    for (const s of sources) {
      if (/^(https?:|wss?:|\*|\/\/)/i.test(s) || /^[a-z0-9-]+\.[a-z]/i.test(s)) problems.push(`${name} allows the remote origin ${s}`);
      if (s === "'unsafe-eval'" || s === "'unsafe-inline'" || s === "'unsafe-hashes'") problems.push(`${name} allows ${s}`);
    }
  }
  if ((csp['object-src'] ?? []).join(' ') !== "'none'") problems.push("object-src must be 'none'");
  if ((csp['base-uri'] ?? []).join(' ') !== "'none'" && (csp['base-uri'] ?? []).join(' ') !== "'self'") problems.push("base-uri must be 'none' or 'self'");
  return problems;
}
