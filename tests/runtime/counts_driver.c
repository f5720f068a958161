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
 * Bernstein tests; with the argument --madds, followed by the multiply-adds by phase
 * (m2c_count[0..3]: preparation, counts and exclusion tests, Newton polishing and speculation,
 * derivative method).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "max2code_roots.h"

extern double m2c_count[10];

int main(int argc, char **argv)
{
    int madds = argc > 1 && strcmp(argv[1], "--madds") == 0;
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
        printf("%d %a %d %.0f %.0f %.0f %.0f %.0f", st, st == 1 ? t : 0.0, st == 1 ? graze : 0,
               m2c_count[4], m2c_count[5], m2c_count[6], m2c_count[7], m2c_count[9]);
        if (madds)
            printf(" %.0f %.0f %.0f %.0f", m2c_count[0], m2c_count[1], m2c_count[2], m2c_count[3]);
        printf("\n");
    }
    return 0;
}
