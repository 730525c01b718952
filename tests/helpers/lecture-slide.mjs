// Lecture 000's winged-edge EDGE TABLE as the slide prints it, one string per row:
// e  S  E  L  R, then the wings S:L S:R E:L E:R ('-': no face). Tests compare against it.
export const SLIDE_EDGE_TABLE = Object.freeze([
  'e1 v1 v3 - F1 e2 e2 e4 e3',
  'e2 v1 v2 F1 - e1 e1 e3 e6',
  'e3 v2 v3 F1 F2 e2 e5 e1 e4',
  'e4 v3 v4 - F2 e1 e3 e7 e5',
  'e5 v2 v4 F2 F3 e3 e6 e4 e7',
  'e6 v2 v5 F3 - e5 e2 e7 e7',
  'e7 v4 v5 - F3 e4 e5 e6 e6',
]);
