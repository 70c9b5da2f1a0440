/* The verdicts' names and tones; see claim_verdict.h. */
#include "report/claim_verdict.h"

#include <string.h>

static const char *const kNames[CLAIM_VERDICT_COUNT] = {
    "reproduced",            "refuted",             "fails a stronger reading", "fails under gtlab's setting",
    "no visible difference", "limitation measured", "not significant",          "not testable here"};

const char *claim_verdict_name(claim_verdict v) { return (unsigned)v < CLAIM_VERDICT_COUNT ? kNames[v] : "?"; }

claim_tone claim_verdict_tone(claim_verdict v)
{
    switch (v) {
    case CLAIM_REPRODUCED:
    case CLAIM_NO_VISIBLE_DIFFERENCE: return CLAIM_TONE_HOLDS;
    case CLAIM_REFUTED:
    case CLAIM_FAILS_STRONGER_READING:
    case CLAIM_FAILS_GTLAB_SETTING: return CLAIM_TONE_FAILS;
    case CLAIM_LIMITATION_MEASURED: return CLAIM_TONE_MEASURED;
    default: return CLAIM_TONE_OPEN;
    }
}

int claim_verdict_from_name(const char *text)
{
    for (int v = 0; v < CLAIM_VERDICT_COUNT; ++v)
        if (strcmp(text, kNames[v]) == 0)
            return v;
    return -1;
}
