// @ts-check
// The subdivision lesson page: the skeleton runs the lesson object.
import { runLessonPage } from '../../pages/lesson-page.js';
import { subdivisionLesson } from './lesson.js';

runLessonPage(subdivisionLesson);
