/*
 * max2code_roots_driver.c -- line-oriented front end to the C runtime, used
 * by the tests (and handy for measuring by hand).
 *
 * Each input line:   METHOD[:EPS] TMAX DEGREE C0 C1 ... CDEGREE
 * (numbers in any strtod form; the tests send hex floats so that values
 * cross exactly; "inf"/"nan" are accepted).  METHOD:EPS calls
 * m2c_first_root_skin with the contact skin EPS (METHOD is then ignored).
 * Each output line:
 *   STATUS T GRAZE      with T printed as %.17g (nan unless STATUS is 1),
 * and with the argument --time a fourth column: the call's thread CPU time
 * in ns (the fuzz tests' hang detector).
 * A malformed line prints "error".  DEGREE beyond 16 is passed through so that
 * the runtime's own validation is exercised (at most 17 coefficients read).
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "max2code_roots.h"

#define MAX_READ 16

static int parse_line(char *line, int *method, int *skin, double *eps, int *degree,
                      double *tmax, double c[MAX_READ + 1])
{
    char *p = line, *end;
    *method = (int)strtol(p, &end, 10);
    if (end == p) return 0;
    p = end;
    *skin = *p == ':'; /* else m2c_first_root_ex */
    if (*skin) {
        *eps = strtod(p + 1, &end);
        if (end == p + 1) return 0;
        p = end;
    }
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

static double cpu_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return (double)ts.tv_sec * 1e9 + (double)ts.tv_nsec;
}

int main(int argc, char **argv)
{
    int timed = argc > 1 && strcmp(argv[1], "--time") == 0;
    char line[8192];
    while (fgets(line, sizeof line, stdin) != NULL) {
        int method, skin, degree, graze = 0;
        double tmax, eps = 0, c[MAX_READ + 1], t = NAN;
        if (strspn(line, " \t\r\n") == strlen(line))
            continue;
        if (!parse_line(line, &method, &skin, &eps, &degree, &tmax, c)) {
            puts("error");
            continue;
        }
        double t0 = timed ? cpu_ns() : 0;
        int st = !skin ? m2c_first_root_ex(c, degree, tmax, &t, method, &graze)
                           : m2c_first_root_skin(c, degree, tmax, eps, &t, &graze);
        double ns = timed ? cpu_ns() - t0 : 0;
        if (st != 1) {
            t = NAN;
            graze = 0;
        }
        if (timed)
            printf("%d %.17g %d %.0f\n", st, t, graze, ns);
        else
            printf("%d %.17g %d\n", st, t, graze);
    }
    return 0;
}
