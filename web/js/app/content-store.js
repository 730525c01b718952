// Large parts of a lesson state (an imported mesh) kept in IndexedDB by the SHA-256 of
// their text, so the link and local storage only hold a reference to them (issue 13, item
// 12; docs/state-format.md, "Large fields"). share-link.js decides what is stored here and
// checks, when reading, that the text still has its hash.
//
// One database per origin, `wingspline-content`, one object store `content`:
// { hash: 'sha256-<64 hex>', text, used: <ms since 1970> }. The MAX_ENTRIES most recently
// used entries are kept; older ones are dropped when a new one is written (a link that
// refers to a dropped entry says so and asks for the file).

const DB_NAME = 'wingspline-content';
const STORE = 'content';
export const MAX_ENTRIES = 16;

function request(req) {
  return new Promise((resolve, reject) => {
    req.onsuccess = () => resolve(req.result);
    req.onerror = () => reject(req.error ?? new Error('IndexedDB request failed'));
  });
}

function done(tx) {
  return new Promise((resolve, reject) => {
    tx.oncomplete = () => resolve();
    tx.onerror = () => reject(tx.error ?? new Error('IndexedDB transaction failed'));
    tx.onabort = () => reject(tx.error ?? new Error('IndexedDB transaction aborted'));
  });
}

// A content store on this browser's IndexedDB; every method rejects when IndexedDB is not
// available (some private modes), and the caller then keeps the value inline.
export function createContentStore() {
  let opened = null;
  function open() {
    if (!opened) {
      opened = new Promise((resolve, reject) => {
        if (typeof indexedDB === 'undefined') { reject(new Error('IndexedDB is not available')); return; }
        const req = indexedDB.open(DB_NAME, 1);
        req.onupgradeneeded = () => {
          const store = req.result.createObjectStore(STORE, { keyPath: 'hash' });
          store.createIndex('used', 'used');
        };
        req.onsuccess = () => resolve(req.result);
        req.onerror = () => reject(req.error ?? new Error('IndexedDB could not be opened'));
        req.onblocked = () => reject(new Error('IndexedDB is blocked by another tab'));
      });
      opened.catch(() => { opened = null; });
    }
    return opened;
  }
  // Hashes known to be in the database (this page wrote or read them): no second write.
  const known = new Set();

  return {
    // A hash another context of the page (the import worker) has just written: no second write.
    markStored(hash) {
      known.add(hash);
    },
    async get(hash) {
      const db = await open();
      const tx = db.transaction(STORE, 'readwrite');
      const store = tx.objectStore(STORE);
      const entry = await request(store.get(hash));
      if (entry) store.put({ ...entry, used: Date.now() });
      await done(tx);
      if (!entry || typeof entry.text !== 'string') return null;
      known.add(hash);
      return entry.text;
    },
    async put(hash, text) {
      if (known.has(hash)) return;
      const db = await open();
      const tx = db.transaction(STORE, 'readwrite');
      const store = tx.objectStore(STORE);
      store.put({ hash, text, used: Date.now() });
      // Keep the newest MAX_ENTRIES: walk the index from the oldest and drop the surplus.
      const count = await request(store.count());
      let surplus = count - MAX_ENTRIES;
      if (surplus > 0) {
        const cursorReq = store.index('used').openCursor();
        await new Promise((resolve, reject) => {
          cursorReq.onsuccess = () => {
            const cursor = cursorReq.result;
            if (!cursor || surplus <= 0) { resolve(); return; }
            if (cursor.value.hash !== hash) { cursor.delete(); surplus -= 1; known.delete(cursor.value.hash); }
            cursor.continue();
          };
          cursorReq.onerror = () => reject(cursorReq.error);
        });
      }
      await done(tx);
      known.add(hash);
    },
  };
}
