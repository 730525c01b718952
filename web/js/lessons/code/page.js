// @ts-check
// The "Program the structure" lesson page: the skeleton runs the lesson object.
import { runLessonPage } from '../../pages/lesson-page.js';
import { codeLesson } from './lesson.js';

runLessonPage(codeLesson);
