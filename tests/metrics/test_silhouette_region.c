/* The silhouette region against configurations whose region is known in
 * closed form: a smooth surface has none, a depth step a band of 2 r + 2
 * columns, a step below the relative threshold none, a background column a
 * band on both of its sides; region and interior always partition the mask. */
#include <stdlib.h>

#include "metrics/silhouette_region.h"
#include "tests/check.h"

enum { W = 40, H = 30 };

static float depth[W * H], mask[W * H], region[W * H], interior[W * H];

static void fill(double left, double right, int step_column)
{
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            depth[y * W + x] = (float)(x < step_column ? left + 0.001 * x : right);
            mask[y * W + x] = 1.0f;
        }
}

/* Checks the region is exactly columns [first, last] and that region and
 * interior partition the mask. */
static void check_columns(int first, int last, const char *what)
{
    int wrong = 0, partition = 0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            int i = y * W + x, expected = mask[i] >= 0.5f && x >= first && x <= last;
            wrong += region[i] != (float)expected;
            partition += region[i] + interior[i] != (mask[i] >= 0.5f ? 1.0f : 0.0f);
        }
    CHECK_MSG(wrong == 0, "%s: %d pixels wrong", what, wrong);
    CHECK_MSG(partition == 0, "%s: %d pixels not partitioned", what, partition);
}

int main(void)
{
    for (int r = 0; r <= 3; ++r) {
        fill(1.0, 1.0, W); /* a smooth ramp over the whole image: no edge, the border is none */
        CHECK(silhouette_region(depth, mask, W, H, r, 0.1, region, interior) == 0);
        check_columns(1, 0, "smooth");
        fill(1.0, 2.0, 20); /* a step between columns 19 and 20 */
        CHECK(silhouette_region(depth, mask, W, H, r, 0.1, region, interior) == 0);
        check_columns(19 - r, 20 + r, "far step");
        fill(2.0, 1.0, 20); /* the near side on the right: the same band */
        CHECK(silhouette_region(depth, mask, W, H, r, 0.1, region, interior) == 0);
        check_columns(19 - r, 20 + r, "near step");
        fill(1.0, 1.05, 20); /* a 5% step under a 10% threshold */
        CHECK(silhouette_region(depth, mask, W, H, r, 0.1, region, interior) == 0);
        check_columns(1, 0, "small step");
        fill(1.0, 1.0, W);
        for (int y = 0; y < H; ++y)
            mask[y * W + 10] = 0.0f; /* background column 10: bands on both sides, never the column itself */
        CHECK(silhouette_region(depth, mask, W, H, r, 0.1, region, NULL) == 0);
        int wrong = 0;
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x)
                wrong += region[y * W + x] != (float)(x != 10 && abs(x - 10) <= r + 1);
        CHECK_MSG(wrong == 0, "background column, radius %d: %d pixels wrong", r, wrong);
    }
    return check_report("metrics_silhouette_region");
}
