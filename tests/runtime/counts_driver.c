/*
 * counts_driver.c -- the C runtime's answers and its own cost accounting, per solve, for
 * tests/runtime/test_python_control_flow.py (built with -DM2C_COUNT against
 * runtime/c/max2code_roots.c).
 *
 * Each input line:   METHOD EPS TMAX DEGREE C0 .. CDEGREE   (hex floats; inf/nan accepted)
 * EPS != 0 calls m2c_first_root_skin (METHOD then ignored), else m2c_first_root_ex.
 * Each output line:  STATUS T GRAZE PLAIN PRECISE POINTS DERIVATIVE BERNSTEIN
 * with T as %a (0 unless STATUS is 1) and the counters of m2c_count: Newton steps with
 * plain and with compensated evaluation, Taylor points, derivative-method calls and
 * Bernstein tests.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "max2code_roots.h"

extern double m2c_count[10];

int main(void)
{
    char line[8192];
    while (fgets(line, sizeof line, stdin) != NULL) {
        char *p = line, *end;
        int method = (int)strtol(p, &end, 10);
        if (end == p)
            continue;
        p = end;
        double eps = strtod(p, &end);
        p = end;
        double tmax = strtod(p, &end);
        p = end;
        int degree = (int)strtol(p, &end, 10);
        p = end;
        double c[M2C_MAX_DEGREE + 1] = {0};
        for (int i = 0; i <= degree && i <= M2C_MAX_DEGREE; i++) {
            c[i] = strtod(p, &end);
            p = end;
        }
        memset(m2c_count, 0, sizeof m2c_count);
        double t = NAN;
        int graze = 0;
        int st = eps != 0 ? m2c_first_root_skin(c, degree, tmax, eps, &t, &graze)
                          : m2c_first_root_ex(c, degree, tmax, &t, method, &graze);
        printf("%d %a %d %.0f %.0f %.0f %.0f %.0f\n", st, st == 1 ? t : 0.0, st == 1 ? graze : 0,
               m2c_count[4], m2c_count[5], m2c_count[6], m2c_count[7], m2c_count[9]);
    }
    return 0;
}
