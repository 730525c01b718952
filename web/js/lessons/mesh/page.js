// @ts-check
// The mesh lesson page: the skeleton runs the lesson object.
import { runLessonPage } from '../../pages/lesson-page.js';
import { meshLesson } from './lesson.js';

runLessonPage(meshLesson);
