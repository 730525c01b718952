// @ts-check
// A code editor for a student's JavaScript: CodeMirror 6 (bundled into the page at build
// time by esbuild, so no CDN and no inline script), with line numbers, JavaScript highlighting, bracket
// matching, undo, Ctrl+/ to comment, Tab to indent (Escape then Tab leaves the editor, CodeMirror's own
// convention for keyboard users), an error marked at its line and column, and that line lit.
// The editor lives in a shadow root: CodeMirror writes its styles as a <style> element into a
// document, which the page's CSP (style-src 'self') refuses, and as a constructed style sheet
// into a shadow root, which it allows. Its look (THEME) uses the page's colour variables, which
// reach into the shadow root.
// Offers: createCodeEditor({parent, label, doc, onChange, onRun}) (onRun: Ctrl/Cmd+Enter) -> {view, text, setText(text),
//   showError({line, column, message} | null), markLine(line | null), focus()}.
import { EditorView, keymap, lineNumbers, highlightActiveLine, Decoration } from '@codemirror/view';
import { EditorState, StateEffect, StateField } from '@codemirror/state';
import { standardKeymap, history, historyKeymap, indentWithTab, toggleComment, indentMore, indentLess } from '@codemirror/commands';
import { javascriptLanguage } from '@codemirror/lang-javascript';
import { syntaxHighlighting, HighlightStyle, bracketMatching, indentOnInput } from '@codemirror/language';
import { tags } from '@lezer/highlight';

// A set of decorations that an effect replaces (null: none), mapped through edits meanwhile.
/** @param {import('@codemirror/state').StateEffectType<any>} effect @param {(value: any, state: EditorState) => import('@codemirror/view').DecorationSet} make */
const decorationsOf = (effect, make) => StateField.define({
  create: () => Decoration.none,
  update(deco, tr) {
    let next = deco.map(tr.changes);
    for (const e of tr.effects) if (e.is(effect)) next = e.value === null ? Decoration.none : make(e.value, tr.state);
    return next;
  },
  provide: (f) => EditorView.decorations.from(f),
});

// The error's place: a wavy mark from its column to the end of its line (a small decoration
// of our own: CodeMirror's lint package would add 8 KB for one diagnostic at a time).
/** @type {import('@codemirror/state').StateEffectType<{ from: number, to: number, message: string } | null>} */
const setErrorMark = StateEffect.define();
const errorMark = decorationsOf(setErrorMark, (at) => Decoration.set([
  Decoration.mark({ class: 'cm-error-mark', attributes: { title: at.message } }).range(at.from, Math.max(at.to, at.from + 1))]));

// The line lit (the error's): a line decoration.
/** @type {import('@codemirror/state').StateEffectType<number | null>} */
const setTraceLine = StateEffect.define();
const traceLine = decorationsOf(setTraceLine, (line, state) => (line < 1 || line > state.doc.lines ? Decoration.none
  : Decoration.set([Decoration.line({ class: 'cm-trace-line' }).range(state.doc.line(line).from)])));

// Highlighting in the page's colours (web/css/code.css sets --code-* for the light and the
// dark theme, each readable on the editor's background): CodeMirror's default colours are
// for a light background only.
const HIGHLIGHT = HighlightStyle.define([
  { tag: [tags.keyword, tags.controlKeyword, tags.definitionKeyword, tags.moduleKeyword, tags.operatorKeyword], color: 'var(--code-keyword)' },
  { tag: [tags.string, tags.special(tags.string), tags.regexp], color: 'var(--code-string)' },
  { tag: [tags.number, tags.bool, tags.null, tags.atom], color: 'var(--code-number)' },
  { tag: [tags.comment, tags.lineComment, tags.blockComment], color: 'var(--code-comment)', fontStyle: 'italic' },
  { tag: [tags.function(tags.variableName), tags.definition(tags.variableName), tags.definition(tags.propertyName)], color: 'var(--code-definition)' },
  { tag: tags.invalid, color: 'var(--code-invalid)', textDecoration: 'underline wavy' },
]);

const THEME = EditorView.theme({
  '&': { border: '1px solid var(--line)', borderRadius: 'var(--radius, 4px)', background: 'var(--panel)', color: 'var(--ink)', fontSize: '0.95rem', maxHeight: '55vh' },
  '&.cm-focused': { outline: '3px solid var(--focus)', outlineOffset: '1px' },
  '.cm-scroller': { fontFamily: "ui-monospace, 'DejaVu Sans Mono', monospace", lineHeight: '1.45' },
  '.cm-content, .cm-gutter': { minHeight: '11.5rem' },
  '.cm-content': { caretColor: 'var(--ink)' },
  '.cm-gutters': { background: 'var(--bg)', color: 'var(--muted)', borderRight: '1px solid var(--line)' },
  '.cm-activeLine': { background: 'color-mix(in srgb, var(--accent) 8%, transparent)' },
  '.cm-trace-line': { background: 'color-mix(in srgb, var(--c4) 28%, transparent)' },
  '.cm-error-mark': { textDecoration: 'underline wavy var(--code-invalid)', textDecorationSkipInk: 'none', background: 'color-mix(in srgb, var(--code-invalid) 12%, transparent)' },
});

/**
 * @param {{ parent: HTMLElement, label: string, doc: string, onChange: (text: string) => void, onRun?: () => void }} options
 */
export function createCodeEditor({ parent, label, doc, onChange, onRun }) {
  let quiet = false; // true while setText writes: not the student's change
  const host = document.createElement('div');
  host.className = 'code-editor-host';
  parent.append(host);
  const root = host.attachShadow({ mode: 'open' });
  const mount = document.createElement('div');
  root.append(mount);
  const view = new EditorView({
    root,
    parent: mount,
    state: EditorState.create({
      doc,
      extensions: [
        lineNumbers(), history(), indentOnInput(), bracketMatching(),
        highlightActiveLine(), syntaxHighlighting(HIGHLIGHT), javascriptLanguage, errorMark,
        traceLine, THEME, EditorState.tabSize.of(2),
        keymap.of([{ key: 'Mod-Enter', run: () => { onRun?.(); return true; } }, ...standardKeymap, ...historyKeymap, indentWithTab,
          { key: 'Mod-/', run: toggleComment }, { key: 'Mod-]', run: indentMore }, { key: 'Mod-[', run: indentLess }]),
        // tabindex 0 on the editable text (already in the tab order): checkers such as axe
        // then see that the scrolling box has keyboard access.
        EditorView.contentAttributes.of({ 'aria-label': label, spellcheck: 'false', autocapitalize: 'off', autocorrect: 'off', tabindex: '0' }),
        EditorView.updateListener.of((u) => { if (u.docChanged && !quiet) onChange(u.state.doc.toString()); }),
      ],
    }),
  });
  const pos = (line, column) => {
    const doc = view.state.doc;
    const l = doc.line(Math.min(Math.max(1, line), doc.lines));
    return Math.min(l.from + Math.max(0, (column ?? 1) - 1), l.to);
  };
  return {
    view,
    get text() { return view.state.doc.toString(); },
    setText(text) {
      if (text === view.state.doc.toString()) return;
      quiet = true;
      try {
        view.dispatch({ changes: { from: 0, to: view.state.doc.length, insert: text } });
      } finally {
        quiet = false;
      }
    },
    /** @param {{ line: number, column?: number, message: string } | null} error */
    showError(error) {
      if (!error || !error.line) { view.dispatch({ effects: setErrorMark.of(null) }); return; }
      const from = pos(error.line, error.column);
      const to = Math.min(view.state.doc.length, Math.max(from + 1, view.state.doc.lineAt(from).to));
      view.dispatch({ effects: setErrorMark.of(from < to ? { from, to, message: error.message } : null) });
    },
    /** @param {number | null} line */
    markLine(line) {
      view.dispatch({ effects: setTraceLine.of(line) });
      if (line !== null && line >= 1 && line <= view.state.doc.lines) {
        view.dispatch({ effects: EditorView.scrollIntoView(view.state.doc.line(line).from, { y: 'nearest' }) });
      }
    },
    focus() { view.focus(); },
  };
}
