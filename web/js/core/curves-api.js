// Curves part of the API (issue 5). Filled in by the curves core.
export function createCurvesApi(/* raw */) {
  return {};
}
