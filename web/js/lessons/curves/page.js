// @ts-check
// The curve explorer page (curves.html, written by the build from web/templates/lesson.html).
import { runLesson } from '../../app/shell.js';
import { lesson } from './lesson.js';

runLesson(lesson);
