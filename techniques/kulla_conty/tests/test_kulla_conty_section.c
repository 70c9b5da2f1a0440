/* The Kulla-Conty section from made-up results (no study runs): the sizes
 * and losses reach summary.json from their fields, and the smallest size
 * "a viewer cannot see" is the first whose furnace error is under the Weber
 * fraction (none when no size is). */
#include "kulla_conty/kulla_conty_section.h"
#include "report/claim_thresholds.h"
#include "tests/section_test.h"

static void made_up(kulla_conty_result *r, double furnace_at_16)
{
    *r = (kulla_conty_result){.request = {32, {4, 8, 16, 32}, 4, 48, 8}};
    const double furnace[4] = {0.2, 0.05, furnace_at_16, furnace_at_16 / 4.0};
    for (int i = 0; i < 4; ++i)
        r->by_size[i] = (kulla_conty_size_row){r->request.sizes[i], 0.1 / (i + 1), 0.05 / (i + 1), furnace[i]};
    for (int i = 0; i < KULLA_CONTY_LOSS_ROWS; ++i)
        r->loss[i] = (kulla_conty_loss_row){(i + 1) / 5.0, 1.0 - 0.05 * i, 0.05 * i};
}

int main(void)
{
    static kulla_conty_result r;
    made_up(&r, 0.5 * CLAIM_WEBER_FRACTION);
    CHECK(kulla_conty_smallest_invisible_size(&r) == 16);
    made_up(&r, 2.0 * CLAIM_WEBER_FRACTION);
    CHECK(kulla_conty_smallest_invisible_size(&r) == 32);
    made_up(&r, 1.0);
    CHECK(kulla_conty_smallest_invisible_size(&r) == 0);

    section_test t;
    section_test_begin(&t, "kulla_conty_section", NULL);
    made_up(&r, 0.5 * CLAIM_WEBER_FRACTION);
    gt_error e;
    CHECK(kulla_conty_section(&t.ctx, &r, &e) == 0);
    const cJSON *json = cJSON_GetObjectItem(t.ctx.summary, "kulla_conty");
    const cJSON *sizes = cJSON_GetObjectItem(json, "sizes"), *loss = cJSON_GetObjectItem(json, "energy_lost");
    CHECK(cJSON_GetArraySize(sizes) == 4 && cJSON_GetArraySize(loss) == KULLA_CONTY_LOSS_ROWS);
    const cJSON *third = cJSON_GetArrayItem(sizes, 2);
    CHECK(cJSON_GetObjectItem(third, "size")->valueint == 16);
    CHECK(cJSON_GetObjectItem(third, "max_furnace_error")->valuedouble == 0.5 * CLAIM_WEBER_FRACTION);
    CHECK(cJSON_GetObjectItem(cJSON_GetArrayItem(loss, 4), "energy_lost")->valuedouble == 0.2);
    section_test_end(&t);
    return check_report("test_kulla_conty_section");
}
