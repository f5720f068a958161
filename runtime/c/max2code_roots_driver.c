/*
 * max2code_roots_driver.c -- line-oriented front end to the C runtime, used
 * by the tests (and handy for measuring by hand).
 *
 * Each input line:   METHOD TMAX DEGREE C0 C1 ... CDEGREE
 * (numbers in any strtod form; the tests send hex floats so that values
 * cross exactly; "inf"/"nan" are accepted).  Each output line:
 *   STATUS T GRAZE      with T printed as %.17g (nan unless STATUS is 1).
 * A malformed line prints "error".  DEGREE beyond 8 is passed through so that
 * the runtime's own validation is exercised (at most 16 coefficients read).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "max2code_roots.h"

#define MAX_READ 16

static int parse_line(char *line, int *method, double *tmax, int *degree,
                      double c[MAX_READ + 1])
{
    char *p = line, *end;
    *method = (int)strtol(p, &end, 10);
    if (end == p) return 0;
    p = end;
    *tmax = strtod(p, &end);
    if (end == p) return 0;
    p = end;
    *degree = (int)strtol(p, &end, 10);
    if (end == p) return 0;
    p = end;
    int want = *degree < 0 ? 0 : (*degree > MAX_READ ? MAX_READ : *degree) + 1;
    for (int i = 0; i < want; i++) {
        c[i] = strtod(p, &end);
        if (end == p) return 0;
        p = end;
    }
    return 1;
}

int main(void)
{
    char line[4096];
    while (fgets(line, sizeof line, stdin) != NULL) {
        int method, degree, graze = 0;
        double tmax, c[MAX_READ + 1], t = NAN;
        if (strspn(line, " \t\r\n") == strlen(line))
            continue;
        if (!parse_line(line, &method, &tmax, &degree, c)) {
            puts("error");
            continue;
        }
        int st = m2c_first_root_ex(c, degree, tmax, &t, method, &graze);
        if (st != 1) {
            t = NAN;
            graze = 0;
        }
        printf("%d %.17g %d\n", st, t, graze);
    }
    return 0;
}
