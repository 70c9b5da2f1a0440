#include "core/optics/sky_environment.h"

#include <math.h>
#include <string.h>

int environment_parse(const char *name, environment_kind *kind)
{
    if (strcmp(name, "white") == 0)
        return *kind = ENVIRONMENT_WHITE, 0;
    if (strcmp(name, "sky") == 0)
        return *kind = ENVIRONMENT_SKY, 0;
    return -1;
}

const char *environment_name(environment_kind kind) { return kind == ENVIRONMENT_SKY ? "sky" : "white"; }

double sky_radiance(vec3 w)
{
    const double elevation = 30.0 * M_PI / 180.0, azimuth = 35.0 * M_PI / 180.0;
    const double s[3] = {cos(elevation) * sin(azimuth), sin(elevation), cos(elevation) * cos(azimuth)};
    double w_dot_s = w.x * s[0] + w.y * s[1] + w.z * s[2];
    return 0.2 + 0.8 * fmax(0.0, (double)w.y) + 5.0 * exp(32.0 * (w_dot_s - 1.0));
}
