// @ts-check
import { runLessonPage } from '../../pages/lesson-page.js';
import { lesson } from './lesson.js';

runLessonPage(lesson);
