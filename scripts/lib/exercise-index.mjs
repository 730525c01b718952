// The exercise gallery's index: dist/exercises/index.json lists every exercise
// shipped in web/exercises/ (id, title, lesson, kind, source), each read by the same reader
// the pages use (web/js/exercise/format.js). A file that does not read stops the build with
// its name and the field: a broken exercise never reaches the site.
import fs from 'node:fs';
import path from 'node:path';
import { pathToFileURL } from 'node:url';

export async function exerciseIndex(repoRoot) {
  const dir = path.join(repoRoot, 'web', 'exercises');
  const { parseExercise } = await import(pathToFileURL(path.join(repoRoot, 'web', 'js', 'exercise', 'format.js')).href);
  const { lessons } = await import(pathToFileURL(path.join(repoRoot, 'web', 'js', 'lessons', 'registry.js')).href);
  const lessonIds = lessons.map((l) => l.id);
  const files = fs.existsSync(dir) ? fs.readdirSync(dir).filter((f) => f.endsWith('.json') && f !== 'index.json').sort() : [];
  const entries = [];
  for (const file of files) {
    let exercise;
    try {
      exercise = parseExercise(fs.readFileSync(path.join(dir, file), 'utf8'), { lessonIds });
    } catch (err) {
      throw new Error(`web/exercises/${file}: ${err.message}`);
    }
    if (exercise.id !== file.replace(/\.json$/, '')) throw new Error(`web/exercises/${file}: its id must be "${file.replace(/\.json$/, '')}" (the file's name), not "${exercise.id}"`);
    entries.push({ id: exercise.id, title: exercise.title, lesson: exercise.lesson, kind: exercise.check.kind, source: exercise.source ?? '', order: exercise.order ?? 0 });
  }
  // Course order, then the exercise's `order` within its lesson (the lecture's order).
  entries.sort((a, b) => lessonIds.indexOf(a.lesson) - lessonIds.indexOf(b.lesson) || a.order - b.order || a.id.localeCompare(b.id));
  return { format: 'wingspline-exercise-index', version: 1, exercises: entries };
}
