// @ts-check
import { runLesson } from '../../app/shell.js';
import { lesson } from './lesson.js';

runLesson(lesson);
