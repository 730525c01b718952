// @ts-check
// The subdivision lesson page: the skeleton runs the lesson object.
import { runLesson } from '../../app/shell.js';
import { subdivisionLesson } from './lesson.js';

runLesson(subdivisionLesson);
