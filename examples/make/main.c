/* One fixed scene: when do the two circles touch? (See ../README.md for the scene.) */
#include <stdio.h>

#include "circles.h"

int main(void)
{
    /* x1, y1, vx1, vy1, ax1, ay1, r1, x2, y2, vx2, vy2, ax2, ay2, r2 */
    const double p[circles_NPARAMS] = {0, 0, 1, 0, 0.5, 0, 1, 10, 0, -1, 0, 0, 0, 0.5};
    double t;
    if (circles_first_root(p, 100.0, &t) != 1) {
        printf("no collision\n");
        return 1;
    }
    printf("collision at t = %.17g\n", t);
    return 0;
}
