// @ts-check
// The curve explorer page (curves.html, written by the build from web/templates/lesson.html).
import { runLessonPage } from '../../pages/lesson-page.js';
import { lesson } from './lesson.js';

runLessonPage(lesson);
