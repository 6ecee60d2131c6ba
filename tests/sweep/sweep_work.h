/* The work of a sweep query for tests that compare strategies (a kept cursor against queries
 * from the root): its distances (fl_closest.visited: element solves) plus its box distances
 * (fl_sweep_cursor_box_tests). A query from the root decides most regions by their boxes
 * (query.c, issue #9), so its distances alone undercount it. */
#ifndef SWEEP_WORK_H
#define SWEEP_WORK_H

#include <stdint.h>

#include "fl_test.h"
#include "sweep/sweep_internal.h"

/* One exact query from the root (a new cursor, as fl_sweep_closest does), posed when `pose`
 * is given; fills r and returns its work. */
static inline size_t sweep_fresh_work(const fl_sweep *s, const fl_sweep_pose *pose,
                                      const double *q, fl_closest *r)
{
    fl_error err;
    fl_sweep_cursor *c = NULL;
    CHECK_STATUS(fl_sweep_cursor_new(s, &c, &err), FL_OK, &err);
    if (!c) return SIZE_MAX;
    if (pose)
        CHECK_STATUS(fl_sweep_cursor_closest_posed(c, pose, q, 0, r, &err), FL_OK, &err);
    else
        CHECK_STATUS(fl_sweep_cursor_closest(c, q, 0, r, &err), FL_OK, &err);
    size_t work = r->visited + fl_sweep_cursor_box_tests(c);
    fl_sweep_cursor_free(c);
    return work;
}

#endif /* SWEEP_WORK_H */
