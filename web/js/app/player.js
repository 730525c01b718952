// @ts-check
// Plays a sequence of steps (a traversal, a construction): play, pause, step forward and
// back, restart, speed. It runs a timer only while playing (nothing runs for a still
// picture) and reports the step through onStep; the lesson keeps the step in its state.
// When the system asks for reduced motion, playing advances at most one step every two
// seconds (each step is a still picture; nothing flickers by), and stepping by hand is
// unaffected.

// Steps per second while playing under prefers-reduced-motion: reduce.
export const REDUCED_MOTION_STEPS_PER_SECOND = 0.5;

export function prefersReducedMotion() {
  return typeof window !== 'undefined' && !!window.matchMedia?.('(prefers-reduced-motion: reduce)').matches;
}

export function createPlayer({ count, getStep, onStep, stepsPerSecond = 1.5 }) {
  let timer = null;
  let speed = stepsPerSecond;
  const listeners = new Set();
  const notify = () => { for (const fn of listeners) fn(); };
  const effectiveSpeed = () => (prefersReducedMotion() ? Math.min(speed, REDUCED_MOTION_STEPS_PER_SECOND) : speed);

  function schedule() {
    timer = setTimeout(() => {
      const next = getStep() + 1;
      if (next >= count()) {
        pause();
        return;
      }
      onStep(next);
      if (next + 1 >= count()) pause(); else schedule();
    }, 1000 / effectiveSpeed());
  }

  function play() {
    if (timer || count() <= 1) return;
    if (getStep() >= count() - 1) onStep(0);
    schedule();
    notify();
  }

  function pause() {
    if (timer) clearTimeout(timer);
    timer = null;
    notify();
  }

  return {
    play,
    pause,
    toggle() { if (timer) pause(); else play(); },
    get playing() { return timer !== null; },
    next() { pause(); if (getStep() < count() - 1) onStep(getStep() + 1); },
    prev() { pause(); if (getStep() > 0) onStep(getStep() - 1); },
    restart() { pause(); onStep(0); },
    end() { pause(); onStep(Math.max(0, count() - 1)); },
    get speed() { return speed; },
    // The rate actually used: `speed`, capped when reduced motion is asked for.
    get effectiveSpeed() { return effectiveSpeed(); },
    setSpeed(stepsPerSec) {
      speed = Math.min(20, Math.max(0.25, stepsPerSec));
      if (timer) { clearTimeout(timer); schedule(); }
      notify();
    },
    onChange(fn) { listeners.add(fn); return () => listeners.delete(fn); },
  };
}
