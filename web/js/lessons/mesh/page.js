// @ts-check
// The mesh lesson page: the skeleton runs the lesson object.
import { runLesson } from '../../app/shell.js';
import { meshLesson } from './lesson.js';

runLesson(meshLesson);
