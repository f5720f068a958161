/* One fixed scene: when do the two circles touch? (See ../README.md for the scene.) */
#include <stdio.h>

#include "circles.h"

int main(void)
{
    /* The parameters by name (circles_params); circles_first_root takes them as an array. */
    const circles_params q = {.x1 = 0, .y1 = 0, .vx1 = 1, .vy1 = 0, .ax1 = 0.5, .ay1 = 0, .r1 = 1,
                              .x2 = 10, .y2 = 0, .vx2 = -1, .vy2 = 0, .ax2 = 0, .ay2 = 0, .r2 = 0.5};
    double t;
    if (circles_first_root_named(&q, 100.0, &t) != 1) {
        printf("no collision\n");
        return 1;
    }
    printf("collision at t = %.17g\n", t);
    return 0;
}
