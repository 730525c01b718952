// The mesh lesson page (issue 4): the skeleton runs the lesson object.
import { runLessonPage } from '../../pages/lesson-page.js';
import { meshLesson } from './lesson.js';

runLessonPage(meshLesson);
