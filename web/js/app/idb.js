// @ts-check
// The browser's IndexedDB database of Wingspline, one per origin: `wingspline-content`.
//   version 1  `content` { hash, text, used } (index `used`): large fields of a state by the
//              SHA-256 of their text (content-store.js)
//   version 2  + `meta` { hash, chars, used }: the size and last use of each content entry,
//              so the budget is kept without loading the texts
//              + `history` { id, lesson, time, reason, summary, code | json | raw, refs, chars }
//              (index `lesson`): the person's earlier work (work-history.js)
// docs/state-format.md ("Where saved work lives") describes both stores.
export const DB_NAME = 'wingspline-content';
export const DB_VERSION = 2;
// An older Wingspline page in another tab keeps version 1 open: the upgrade waits for it
// this long, then this page goes on without the database (and says so where it matters).
const BLOCKED_MS = 4000;

export function request(req) {
  return new Promise((resolve, reject) => {
    req.onsuccess = () => resolve(req.result);
    req.onerror = () => reject(req.error ?? new Error('IndexedDB request failed'));
  });
}

export function done(tx) {
  return new Promise((resolve, reject) => {
    tx.oncomplete = () => resolve(undefined);
    tx.onerror = () => reject(tx.error ?? new Error('IndexedDB transaction failed'));
    tx.onabort = () => reject(tx.error ?? new Error('IndexedDB transaction aborted'));
  });
}

function upgrade(db, tx, oldVersion) {
  if (oldVersion < 1) db.createObjectStore('content', { keyPath: 'hash' }).createIndex('used', 'used');
  if (oldVersion < 2) {
    const meta = db.createObjectStore('meta', { keyPath: 'hash' });
    db.createObjectStore('history', { keyPath: 'id', autoIncrement: true }).createIndex('lesson', 'lesson');
    // Entries written by version 1 get their size and last use.
    const cursorReq = tx.objectStore('content').openCursor();
    cursorReq.onsuccess = () => {
      const cursor = cursorReq.result;
      if (!cursor) return;
      const { hash, text, used } = cursor.value;
      meta.put({ hash, chars: typeof text === 'string' ? text.length : 0, used: Number.isFinite(used) ? used : Date.now() });
      cursor.continue();
    };
  }
}

// One connection per page (or worker), opened on first use; a page that cannot open it
// (no IndexedDB in some private modes, an older page blocking the upgrade) gets a rejection
// with one sentence, and the next call tries again.
export function createDatabase() {
  let opened = null;
  return {
    open() {
      if (!opened) {
        opened = new Promise((resolve, reject) => {
          let idb;
          try {
            idb = globalThis.indexedDB;
          } catch {
            idb = undefined;
          }
          if (!idb) { reject(new Error('IndexedDB is not available')); return; }
          // The database exists in this browser but cannot be opened now: `unavailable`, which a
          // reader tells apart from a browser without IndexedDB.
          const unavailable = (text) => Object.assign(new Error(text), { unavailable: true });
          let req;
          try {
            req = idb.open(DB_NAME, DB_VERSION);
          } catch (err) {
            reject(unavailable(`IndexedDB could not be opened (${err?.message ?? err})`));
            return;
          }
          let blockedTimer = null;
          req.onupgradeneeded = (event) => upgrade(req.result, req.transaction, event.oldVersion);
          req.onsuccess = () => {
            clearTimeout(blockedTimer);
            const db = req.result;
            // A newer page upgrading the database: let it, this page reopens on next use.
            db.onversionchange = () => { db.close(); opened = null; };
            resolve(db);
          };
          req.onerror = () => { clearTimeout(blockedTimer); reject(unavailable(`IndexedDB could not be opened (${req.error?.message ?? 'refused'})`)); };
          req.onblocked = () => {
            blockedTimer = setTimeout(() => reject(unavailable('this site\'s storage is held by an older Wingspline page in another tab (reload or close it, then reload this one)')), BLOCKED_MS);
          };
        });
        opened.catch(() => { opened = null; });
      }
      return opened;
    },
  };
}
