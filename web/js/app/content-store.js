// @ts-check
// Large parts of a lesson state (an imported mesh) kept in IndexedDB by the SHA-256 of
// their text, so the link and local storage only hold a reference to them
// (docs/state-format.md, "Large fields"). share-link.js decides what is stored here and
// checks, when reading, that the text still has its hash.
//
// Stores `content` { hash, text } and `meta` { hash, chars, used } of the database in
// idb.js. What is kept: every entry that saved work (any lesson's, in local storage) or an
// entry of the history refers to, whatever its age; of the others, the
// KEEP_UNREFERENCED most recently used (an import not yet saved, a link opened a moment ago),
// within the budget of work-history.js. Nothing referred to is ever dropped to make room:
// when the browser refuses a write, the caller says so and keeps the work.
import { createDatabase, request, done } from './idb.js';

export const KEEP_UNREFERENCED = 16;

/**
 * A content store on this browser's IndexedDB; every method rejects when IndexedDB is not
 * available (some private modes), and the caller then keeps the value inline.
 * `referenced()`: the hashes that saved work and the history refer to (a page gives it; a
 * worker, which has no local storage, does not, and never drops anything).
 * @param {{ db?: { open(): Promise<IDBDatabase> }, referenced?: (() => Promise<Set<string>>) | null, budgetChars?: number }} [options]
 */
export function createContentStore({ db = createDatabase(), referenced = null, budgetChars = Infinity } = {}) {
  // Hashes known to be in the database (this page wrote or read them): no second write.
  const known = new Set();
  // Hashes this page shows or is about to save: never dropped by this page's collection.
  const pinned = new Set();

  const store = {
    database: db,
    // A hash another context of the page (the import worker) has just written: no second write.
    markStored(hash) {
      known.add(hash);
      pinned.add(hash);
      store.collect().catch(() => {});
    },
    // Whether this page knows the entry is in the database (it wrote or read it).
    has(hash) {
      return known.has(hash);
    },
    // The hashes the page's current state refers to (the persister tells after each write).
    pin(hashes) {
      pinned.clear();
      for (const h of hashes) pinned.add(h);
    },
    async get(hash) {
      const idb = await db.open();
      const tx = idb.transaction(['content', 'meta'], 'readwrite');
      const entry = await request(tx.objectStore('content').get(hash));
      if (entry && typeof entry.text === 'string') tx.objectStore('meta').put({ hash, chars: entry.text.length, used: Date.now() });
      await done(tx);
      if (!entry || typeof entry.text !== 'string') return null;
      known.add(hash);
      return entry.text;
    },
    async put(hash, text) {
      if (known.has(hash)) return;
      const idb = await db.open();
      const tx = idb.transaction(['content', 'meta'], 'readwrite');
      tx.objectStore('content').put({ hash, text, used: Date.now() });
      tx.objectStore('meta').put({ hash, chars: text.length, used: Date.now() });
      await done(tx);
      known.add(hash);
      pinned.add(hash); // until the persister says what the saved state refers to (pin)
      await store.collect().catch(() => {});
    },
    // { hash: chars } of every entry.
    async sizes() {
      const idb = await db.open();
      const all = await request(idb.transaction('meta').objectStore('meta').getAll());
      return new Map(all.map((m) => [m.hash, m.chars]));
    },
    // Drops the entries nothing refers to, beyond the most recently used KEEP_UNREFERENCED and
    // beyond the budget (with `keep`: hashes the caller knows are referred to, e.g. the
    // history it has just pruned). Resolves to the hashes dropped.
    async collect(keep = null) {
      if (!referenced) return [];
      const refs = keep ?? await referenced();
      for (const h of pinned) refs.add(h);
      const idb = await db.open();
      const metas = await request(idb.transaction('meta').objectStore('meta').getAll());
      let total = metas.filter((m) => refs.has(m.hash)).reduce((sum, m) => sum + m.chars, 0);
      const loose = metas.filter((m) => !refs.has(m.hash)).sort((a, b) => b.used - a.used);
      const drop = [];
      loose.forEach((m, i) => {
        if (i >= KEEP_UNREFERENCED || total + m.chars > budgetChars) drop.push(m.hash);
        else total += m.chars;
      });
      if (!drop.length) return drop;
      const tx = idb.transaction(['content', 'meta'], 'readwrite');
      for (const hash of drop) {
        tx.objectStore('content').delete(hash);
        tx.objectStore('meta').delete(hash);
        known.delete(hash);
      }
      await done(tx);
      return drop;
    },
    // Everything gone (Forget my work on this computer).
    async clear() {
      const idb = await db.open();
      const tx = idb.transaction(['content', 'meta'], 'readwrite');
      tx.objectStore('content').clear();
      tx.objectStore('meta').clear();
      await done(tx);
      known.clear();
      pinned.clear();
    },
  };
  return store;
}
