// The subdivision lesson page (issue 16): the skeleton runs the lesson object.
import { runLesson } from '../../app/shell.js';
import { subdivisionLesson } from './lesson.js';

runLesson(subdivisionLesson);
