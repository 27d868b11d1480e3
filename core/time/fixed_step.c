#include "core/time/fixed_step.h"

#include <math.h>
#include <stdio.h>
#include <time.h>

static double cpu_now(void) { return (double)clock() / CLOCKS_PER_SEC; }

int sl_fixed_step_run(const sl_ini *ini, const sl_fixed_step_model *m, const sl_ns_run_opts *o, sl_ns_result *res,
                      sl_diag *d) {
  double end, dt_cfg, dt_min, every;
  long max_steps;
  int rc = sl_ini_get_real(ini, "time", "end", 1, 0, 0, 1e12, &end, d);
  if (!rc) rc = sl_ini_get_real(ini, "time", "dt", 1, 0, 1e-15, 1e9, &dt_cfg, d);
  if (!rc) rc = sl_ini_get_real(ini, "time", "dt_min", 0, dt_cfg * 1e-6, 0, 1e9, &dt_min, d);
  if (!rc) rc = sl_ini_get_int(ini, "time", "max_steps", 0, 100000000L, 1, 100000000L, &max_steps, d);
  if (!rc) rc = sl_ini_get_real(ini, "output", "every", 0, 0.0, 0.0, 1e12, &every, d);
  if (rc) return rc;
  double t = 0.0, h = dt_cfg;
  long step = 0, steps_here = 0;
  if (o->restart) rc = m->restore(m->user, o->restart, &t, &h, &step, d);
  else rc = m->write(m->user, 0.0, h, 0, d);
  if (rc) return rc;
  res->t_start = t;
  int next_out = every > 0 ? (int)floor(t / every + 1e-9) + 1 : 0;
  const double eps_t = 1e-12 * fmax(1.0, end);
  int steady = 0;
  long n_cut = 0;
  while (t < end - eps_t && !steady && steps_here < max_steps) {
    if (o->interrupt && *o->interrupt) {
      rc = sl_diag_set(d, SL_EFAILED, "interrupted at t = %.6g after %ld steps", t, step);
      break;
    }
    /* land on the next output time, without a sliver of a step before it */
    double t_stop = end;
    if (every > 0 && next_out * every < t_stop) t_stop = next_out * every;
    double hh = h;
    if (fabs(t + hh - t_stop) > eps_t && (t + hh > t_stop || t + 1.05 * hh > t_stop)) hh = t_stop - t;
    double c0 = cpu_now();
    sl_diag ds;
    int its = 0, fatal = 0, src = m->step(m->user, t, hh, &its, &fatal, &ds);
    res->solve += cpu_now() - c0;
    res->nonlinear_iterations += its;
    if (src && fatal) {
      rc = sl_diag_set(d, SL_EFAILED, "at t = %.6g: %s", t, ds.msg);
      break;
    }
    if (src) {
      res->rejected_steps++, ++n_cut;
      h = 0.25 * hh;
      if (h < dt_min) {
        rc = sl_diag_set(d, SL_EFAILED, "step rejected at t = %.6g down to dt = %.3g < dt_min = %.3g: %s", t, h, dt_min,
                         ds.msg);
        break;
      }
      continue;
    }
    m->accept(m->user, hh, &steady);
    t += hh, ++step, ++steps_here;
    if (h < dt_cfg) h = fmin(dt_cfg, 2.0 * h);
    if (o->monitor) o->monitor(o->monitor_user, t, hh, step, its);
    int due = every > 0 ? t >= next_out * every - eps_t : 0;
    if (due || steady || t >= end - eps_t || steps_here >= max_steps) {
      while (every > 0 && t >= next_out * every - eps_t) ++next_out;
      if ((rc = m->write(m->user, t, h, step, d))) break;
    }
  }
  res->steps = step;
  res->t_reached = t;
  res->t_end = end;
  res->step_limit = n_cut ? "convergence of the implicit step" : "fixed dt";
  if (!rc && steady)
    snprintf(res->stop_reason, sizeof res->stop_reason, "steady at t = %.6g %s", t, m->steady_text);
  else if (!rc && t >= end - eps_t)
    snprintf(res->stop_reason, sizeof res->stop_reason, "reached the end time t = %g", end);
  else if (!rc)
    snprintf(res->stop_reason, sizeof res->stop_reason,
             "stopped after max_steps = %ld steps at t = %.6g, before the end time %g (checkpoint saved)", max_steps,
             t, end);
  if (rc == SL_EFAILED) { /* keep the last good state */
    sl_diag d2;
    m->write(m->user, t, h, step, &d2);
  }
  return rc;
}
