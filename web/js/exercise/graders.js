// @ts-check
// Every exercise kind's grade function (the shared contract of kinds/: a pure, DOM-free
// `grade<Kind>({ api, check, subject, answer })` returning the page's check result), by the
// kind's name in exercises. The grader (grade.js, `wingspline grade`) checks submissions here;
// a page's kind calls its own function through its `check()`.
import { gradeTable } from './kinds/table.js';
import { gradeWalk } from './kinds/walk.js';
import { gradeJoint } from './kinds/joint.js';
import { gradeValue } from './kinds/value.js';
import { gradeProperty } from './kinds/property.js';
import { gradeSubdivide } from './kinds/subdivide.js';
import { gradeEdit } from './kinds/edit.js';
import { gradeCode } from './kinds/code.js';

// A grade function may return a promise (code: the function runs in the sandbox, `run`);
// `support` is the lesson's exercise support.
/** @type {Readonly<Record<string, (parts: { api: any, check: any, subject: any, answer: any, support?: any, run?: (request: any) => Promise<any> }) => GradeResult | Promise<GradeResult>>>} */
export const GRADERS = Object.freeze({
  table: gradeTable,
  walk: gradeWalk,
  joint: gradeJoint,
  value: gradeValue,
  property: gradeProperty,
  subdivide: gradeSubdivide,
  edit: gradeEdit,
  code: gradeCode,
});

/** @typedef {{ correct: boolean, partial?: boolean, incomplete?: boolean, findings: Array<{ text: string, hint?: string } | string>, note?: string }} GradeResult */
