/* The verdicts of the claims protocol (docs/claims-protocol.md), their
 * names as the report prints them, and the tone a reader should see at a
 * glance: the claims table (report/claims_table.h) decides them, the writer
 * (report/report_writer.h) colours a table cell that is exactly one of
 * their names. */
#ifndef GTLAB_REPORT_CLAIM_VERDICT_H
#define GTLAB_REPORT_CLAIM_VERDICT_H

typedef enum {
    CLAIM_REPRODUCED,
    CLAIM_REFUTED,
    CLAIM_FAILS_STRONGER_READING,
    CLAIM_FAILS_GTLAB_SETTING,
    CLAIM_NO_VISIBLE_DIFFERENCE,
    CLAIM_LIMITATION_MEASURED,
    CLAIM_NOT_SIGNIFICANT,
    CLAIM_NOT_TESTABLE,
    CLAIM_VERDICT_COUNT
} claim_verdict;

typedef enum {
    CLAIM_TONE_HOLDS,    /* reproduced, no visible difference */
    CLAIM_TONE_FAILS,    /* refuted, fails a stronger reading or under gtlab's setting */
    CLAIM_TONE_MEASURED, /* a limitation measured: neither for nor against */
    CLAIM_TONE_OPEN      /* not significant, not testable here: undecided */
} claim_tone;

/* "reproduced", "refuted", ...; "?" outside the enum. */
const char *claim_verdict_name(claim_verdict v);
claim_tone claim_verdict_tone(claim_verdict v);
/* The verdict whose name is exactly `text`, or -1. */
int claim_verdict_from_name(const char *text);

#endif
