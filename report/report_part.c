/* A stage's part of the report: recorded, written, read and replayed
 * (report_part.h). */
#include "report/report_part.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "core/files/atomic_file.h"
#include "core/files/json_file.h"

enum { PART_FILE_MAX = 64 << 20 };

void report_part_discard(report_part_recorder *rec)
{
    report_free(&rec->doc);
    cJSON_Delete(rec->journal);
    cJSON_Delete(rec->summary);
    free(rec->claims);
    memset(rec, 0, sizeof *rec);
}

int report_part_begin(report_part_recorder *rec, const report_context *run, report_context *stage, gt_error *e)
{
    memset(rec, 0, sizeof *rec);
    report_init(&rec->doc, "part");
    rec->journal = cJSON_CreateArray();
    rec->summary = cJSON_CreateObject();
    rec->claims = calloc(1, sizeof *rec->claims);
    rec->doc.journal = rec->journal;
    *stage = *run;
    stage->doc = &rec->doc;
    stage->summary = rec->summary;
    stage->claims = run->claims ? rec->claims : NULL;
    if (!rec->journal || !rec->summary || !rec->claims) {
        report_part_discard(rec);
        return gt_error_set(e, "report", "out of memory");
    }
    return 0;
}

/* The claims table's rows as a JSON array (NULL: out of memory). */
static cJSON *claims_json(const claims_table *t)
{
    cJSON *rows = cJSON_CreateArray();
    for (int i = 0; rows && i < t->count; ++i)
        if (!cJSON_AddItemToArray(rows, claim_to_json(&t->rows[i])))
            cJSON_Delete(rows), rows = NULL;
    return rows;
}

cJSON *report_part_end(report_part_recorder *rec, const report_context *run, const char *key, const char *project,
                       double seconds, gt_error *e)
{
    cJSON *part = NULL, *claims = NULL;
    if (claims_table_check(rec->claims, e) == 0) { /* a record the protocol refuses: the stage's fault */
        part = cJSON_CreateObject();
        claims = part && !rec->doc.failed ? claims_json(rec->claims) : NULL;
        if (!claims) {
            gt_error_set(e, key, "out of memory while keeping the stage's part of the report");
            cJSON_Delete(part), part = NULL;
        }
    }
    if (part) {
        cJSON_AddStringToObject(part, "gtlab_version", GTLAB_VERSION);
        cJSON_AddStringToObject(part, "quality", study_quality_name(run->study.quality));
        cJSON_AddStringToObject(part, "project", project ? project : "");
        cJSON_AddStringToObject(part, "stage", key);
        cJSON_AddNumberToObject(part, "seconds", seconds);
        cJSON_AddItemToObject(part, "journal", rec->journal);
        cJSON_AddItemToObject(part, "summary", rec->summary);
        cJSON_AddItemToObject(part, "claims", claims);
        rec->journal = rec->summary = NULL; /* the part's now */
    }
    report_part_discard(rec);
    return part;
}

static void part_path(const char *dir, const char *key, char *path, size_t size)
{
    snprintf(path, size, "%s/%s/%s.json", dir, REPORT_PARTS_DIR, key);
}

int report_part_write(const char *dir, const cJSON *part, gt_error *e)
{
    char folder[4096], path[4096];
    snprintf(folder, sizeof folder, "%s/%s", dir, REPORT_PARTS_DIR);
    if (mkdir(folder, 0777) != 0 && errno != EEXIST)
        return gt_error_set(e, folder, "%s", strerror(errno));
    part_path(dir, cJSON_GetObjectItemCaseSensitive(part, "stage")->valuestring, path, sizeof path);
    char *text = cJSON_PrintUnformatted(part);
    if (!text)
        return gt_error_set(e, path, "out of memory");
    int rc = atomic_write_text(path, text, e);
    free(text);
    return rc;
}

static const char *part_text(const cJSON *part, const char *name)
{
    const cJSON *t = cJSON_GetObjectItemCaseSensitive(part, name);
    return cJSON_IsString(t) ? t->valuestring : NULL;
}

/* Whether part has the members a part has, of the right types. */
static int part_is_whole(const cJSON *part, const char *key)
{
    static const char *const texts[] = {"gtlab_version", "quality", "project", "stage"};
    for (size_t i = 0; i < sizeof texts / sizeof texts[0]; ++i)
        if (!part_text(part, texts[i]))
            return 0;
    return strcmp(part_text(part, "stage"), key) == 0 &&
           cJSON_IsNumber(cJSON_GetObjectItemCaseSensitive(part, "seconds")) &&
           cJSON_IsArray(cJSON_GetObjectItemCaseSensitive(part, "journal")) &&
           cJSON_IsObject(cJSON_GetObjectItemCaseSensitive(part, "summary")) &&
           cJSON_IsArray(cJSON_GetObjectItemCaseSensitive(part, "claims"));
}

int report_part_read(const char *dir, const char *key, cJSON **part, gt_error *e)
{
    char path[4096];
    struct stat st;
    part_path(dir, key, path, sizeof path);
    *part = NULL;
    if (stat(path, &st) != 0 && errno == ENOENT)
        return 0;
    if (!(*part = json_file_read_object(path, PART_FILE_MAX, "larger than 64 MiB", "a stage's part of the report", e)))
        return -1;
    if (part_is_whole(*part, key))
        return 1;
    cJSON_Delete(*part), *part = NULL;
    return gt_error_set(e, path, "not the part of stage %s that 'gtlab all' writes (rerun the stage)", key);
}

int report_part_matches(const cJSON *part, study_quality quality, const char *project, char *why, size_t size)
{
    const char *version = part_text(part, "gtlab_version"), *made_at = part_text(part, "quality"),
               *made_for = part_text(part, "project");
    if (strcmp(version, GTLAB_VERSION) != 0)
        return snprintf(why, size, "made by gtlab %s", version), -1;
    if (strcmp(made_at, study_quality_name(quality)) != 0)
        return snprintf(why, size, "made at %s quality", made_at), -1;
    if (strcmp(made_for, project ? project : "") != 0)
        return snprintf(why, size, made_for[0] ? "made for the project %s" : "made without a project%s", made_for),
               -1;
    return 0;
}

double report_part_seconds(const cJSON *part)
{
    return cJSON_GetObjectItemCaseSensitive(part, "seconds")->valuedouble;
}

/* The texts of a journal entry's argument k: a NULL-free array of strings
 * (malloc'd pointers into the entry; count its length), or -1. */
static int entry_texts(const cJSON *entry, int k, const char ***texts, int *count)
{
    const cJSON *a = cJSON_GetArrayItem(entry, k);
    *texts = NULL;
    if (!cJSON_IsArray(a) || !(*texts = malloc(sizeof **texts * (size_t)(cJSON_GetArraySize(a) + 1))))
        return -1;
    *count = 0;
    for (const cJSON *t = a->child; t; t = t->next) {
        if (!cJSON_IsString(t))
            return free(*texts), *texts = NULL, -1;
        (*texts)[(*count)++] = t->valuestring;
    }
    return 0;
}

static const char *entry_text(const cJSON *entry, int k)
{
    const cJSON *t = cJSON_GetArrayItem(entry, k);
    return cJSON_IsString(t) ? t->valuestring : NULL;
}

static int entry_int(const cJSON *entry, int k, int *value)
{
    const cJSON *n = cJSON_GetArrayItem(entry, k);
    return cJSON_IsNumber(n) ? (*value = n->valueint, 0) : -1;
}

static int replay_heading(report *r, const cJSON *entry)
{
    int level;
    const char *text = entry_text(entry, 2);
    return entry_int(entry, 1, &level) == 0 && text ? (report_heading(r, level, text), 0) : -1;
}

static int replay_paragraph(report *r, const cJSON *entry)
{
    const char *text = entry_text(entry, 1);
    return text ? (report_paragraph(r, "%s", text), 0) : -1;
}

enum { TABLE_BEGIN, TABLE_ROW, TABLE_BEST_ROW };

/* A table call: its cells (for a row, as many as the open table's columns). */
static int replay_table(report *r, const cJSON *entry, int call)
{
    int begin = call == TABLE_BEGIN;
    const char **cells;
    int count;
    if (entry_texts(entry, 1, &cells, &count) != 0)
        return -1;
    int ok = begin ? count > 0 : r->table_columns > 0 && count == r->table_columns;
    if (ok && begin)
        report_table_begin(r, count, cells);
    else if (ok && call == TABLE_BEST_ROW)
        report_table_best_row(r, cells);
    else if (ok)
        report_table_row(r, cells);
    free(cells);
    return ok ? 0 : -1;
}

static int replay_table_begin(report *r, const cJSON *entry) { return replay_table(r, entry, TABLE_BEGIN); }
static int replay_table_row(report *r, const cJSON *entry) { return replay_table(r, entry, TABLE_ROW); }
static int replay_table_best_row(report *r, const cJSON *entry) { return replay_table(r, entry, TABLE_BEST_ROW); }

static int replay_table_end(report *r, const cJSON *entry)
{
    (void)entry;
    return report_table_end(r), 0;
}

/* figures [paths] [captions]; comparison [paths] [labels] exposed caption. */
static int replay_figures(report *r, const cJSON *entry, int comparison)
{
    const char **paths = NULL, **captions = NULL, *caption = entry_text(entry, 4);
    int count, captions_count, exposed = 0;
    int ok = entry_texts(entry, 1, &paths, &count) == 0 && entry_texts(entry, 2, &captions, &captions_count) == 0 &&
             count == captions_count && (!comparison || (entry_int(entry, 3, &exposed) == 0 && caption));
    if (ok && comparison)
        report_comparison(r, count, paths, captions, exposed, caption);
    else if (ok)
        report_figures(r, count, paths, captions);
    free(paths);
    free(captions);
    return ok ? 0 : -1;
}

static int replay_row_of_figures(report *r, const cJSON *entry) { return replay_figures(r, entry, 0); }
static int replay_comparison(report *r, const cJSON *entry) { return replay_figures(r, entry, 1); }

static int replay_findings_here(report *r, const cJSON *entry)
{
    (void)entry;
    return report_findings_here(r), 0;
}

static int replay_finding(report *r, const cJSON *entry)
{
    const char *topic = entry_text(entry, 1), *text = entry_text(entry, 2);
    return topic && text ? (report_finding(r, topic, "%s", text), 0) : -1;
}

static int replay_headline(report *r, const cJSON *entry)
{
    report_headline h;
    return headline_from_json(cJSON_GetArrayItem(entry, 1), &h) == 0 ? (report_add_headline(r, &h), 0) : -1;
}

/* One journal entry replayed into r: 0, or -1 when it is not one. */
static int replay_entry(report *r, const cJSON *entry)
{
    static const struct {
        const char *name;
        int (*replay)(report *, const cJSON *);
    } calls[] = {{"heading", replay_heading},         {"paragraph", replay_paragraph},
                 {"table_begin", replay_table_begin}, {"table_row", replay_table_row},
                 {"table_best_row", replay_table_best_row},
                 {"table_end", replay_table_end},     {"figures", replay_row_of_figures},
                 {"comparison", replay_comparison},   {"findings_here", replay_findings_here},
                 {"finding", replay_finding},         {"headline", replay_headline}};
    const char *name = entry_text(entry, 0);
    for (size_t i = 0; name && i < sizeof calls / sizeof calls[0]; ++i)
        if (strcmp(name, calls[i].name) == 0)
            return calls[i].replay(r, entry);
    return -1;
}

int report_part_replay(report_context *ctx, const cJSON *part, const char *what, gt_error *e)
{
    int index = 0;
    for (const cJSON *entry = cJSON_GetObjectItemCaseSensitive(part, "journal")->child; entry;
         entry = entry->next, ++index)
        if (!cJSON_IsArray(entry) || replay_entry(ctx->doc, entry) != 0)
            return gt_error_set(e, what, "journal[%d] is not a call of the report (rerun the stage)", index);
    for (const cJSON *m = cJSON_GetObjectItemCaseSensitive(part, "summary")->child; m; m = m->next)
        if (!cJSON_AddItemToObject(ctx->summary, m->string, cJSON_Duplicate(m, 1)))
            return gt_error_set(e, what, "out of memory");
    index = 0;
    for (const cJSON *row = cJSON_GetObjectItemCaseSensitive(part, "claims")->child; row; row = row->next, ++index)
        if (ctx->claims && claims_table_add_json(ctx->claims, row) != 0)
            return gt_error_set(e, what, "claims[%d] is not a row of the claims table (rerun the stage)", index);
    return 0;
}
