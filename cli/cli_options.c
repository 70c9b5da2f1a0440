/* The declarative option parser of cli_options.h, over getopt_long. */
#define _GNU_SOURCE
#include "cli/cli_options.h"

#include <errno.h>
#include <getopt.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include "cli/cli.h"
#include "core/files/run_inputs.h"

enum { MAX_OPTIONS = 96, HELP_COLUMN = 20 };

static int option_count(const cli_option *o)
{
    int n = 0;
    while (o[n].kind != CLI_KIND_END)
        ++n;
    return n;
}

/* getopt's table: val = 256 + index (or the short letter), then --help. */
static void build_longs(const cli_option *o, int n, struct option *longs, char *shorts)
{
    char *s = shorts;
    for (int i = 0; i < n; ++i) {
        longs[i] = (struct option){o[i].name, o[i].kind == CLI_KIND_FLAG ? no_argument : required_argument, 0,
                                   o[i].short_name ? o[i].short_name : 256 + i};
        if (o[i].short_name) {
            *s++ = o[i].short_name;
            *s++ = ':';
        }
    }
    longs[n] = (struct option){"help", no_argument, 0, 'h'};
    longs[n + 1] = (struct option){0, 0, 0, 0};
    strcpy(s, "h");
}

/* "'x' is neither a nor b", "'x' is not a, b or c". */
static int parse_choice(const cli_option *o, const char *text, int *out, const char *option)
{
    int n = (int)o->hi;
    for (int i = 0; i < n; ++i)
        if (strcmp(text, o->choice(i)) == 0)
            return *out = i, 0;
    char names[256] = "";
    for (int i = 0, k = 0; i < n && k < (int)sizeof names; ++i)
        k += snprintf(names + k, sizeof names - (size_t)k, "%s%s", i == 0 ? "" : i + 1 < n ? ", " : n == 2 ? " nor " : " or ", o->choice(i));
    return cli_failf(option, "'%s' is %s %s", text, n == 2 ? "neither" : "not", names), -1;
}

static int parse_switch(const char *text, int *out, const char *option)
{
    if (strcmp(text, "on") == 0 || strcmp(text, "off") == 0)
        return *out = text[1] == 'n', 0;
    return cli_failf(option, "'%s' is neither on nor off", text), -1;
}

static int parse_number(const cli_option *o, void *dest, const char *text, const char *option)
{
    long n;
    double x;
    switch (o->kind) {
    case CLI_KIND_INT: return cli_parse_int(option, text, (long)o->lo, (long)o->hi, dest);
    case CLI_KIND_INT32: return cli_parse_int(option, text, (long)o->lo, (long)o->hi, &n) ? -1 : (*(int *)dest = (int)n, 0);
    case CLI_KIND_DOUBLE: return cli_parse_double(option, text, o->lo, o->hi, dest);
    default: return cli_parse_double(option, text, o->lo, o->hi, &x) ? -1 : (*(float *)dest = (float)x, 0);
    }
}

static int parse_value(const cli_option *o, void *dest, const char *text)
{
    char option[64];
    snprintf(option, sizeof option, "--%s", o->name);
    switch (o->kind) {
    case CLI_KIND_FLAG: *(int *)dest = 1; return 0;
    case CLI_KIND_STRING: *(const char **)dest = text; return 0;
    case CLI_KIND_CHOICE: return parse_choice(o, text, dest, option);
    case CLI_KIND_SWITCH: return parse_switch(text, dest, option);
    case CLI_KIND_CUSTOM: return o->parse(dest, text);
    default: return parse_number(o, dest, text, option);
    }
}

int cli_list_add(void *list, const char *text)
{
    cli_list *l = list;
    if (l->count == l->capacity)
        return cli_failf(l->option, "more than %d given", l->capacity), -1;
    l->values[l->count++] = text;
    return 0;
}

static int index_of_code(const cli_option *o, int n, int code)
{
    for (int i = 0; i < n; ++i)
        if (code == (o[i].short_name ? o[i].short_name : 256 + i))
            return i;
    return -1;
}

static int check_required(const cli_command *cmd, void *const *dest, int n)
{
    for (int i = 0; i < n; ++i) {
        const cli_option *o = &cmd->options[i];
        if (o->required && o->kind == CLI_KIND_STRING && *(const char **)dest[i] == NULL) {
            if (o->short_name)
                return cli_failf(cmd->command, "-%c/--%s %s is required", o->short_name, o->name, o->value), -1;
            return cli_failf(cmd->command, "--%s %s is required", o->name, o->value), -1;
        }
    }
    return 0;
}

/* Every option value that is no output, and every argument, as an input of
 * the run (those naming no file are left out by run_inputs_note). */
static void note_input(const cli_option *o, const char *text)
{
    char option[64];
    if (o && (o->writes || o->kind == CLI_KIND_FLAG))
        return;
    if (o)
        snprintf(option, sizeof option, "--%s", o->name);
    run_inputs_note(text, o ? option : NULL);
}

/* No output option names one of the run's inputs. */
static int check_outputs(const cli_command *cmd, void *const *dest, int n)
{
    gt_error e;
    for (int i = 0; i < n; ++i) {
        const cli_option *o = &cmd->options[i];
        if (o->writes && o->kind == CLI_KIND_STRING && run_inputs_check_output(*(const char **)dest[i], &e) != 0)
            return cli_fail(&e), -1;
    }
    return 0;
}

/* Levenshtein's distance between a and b (insertions, deletions and
 * substitutions of one character), over names shorter than 64. */
static int edit_distance(const char *a, const char *b)
{
    int row[64], n = (int)strlen(b);
    if (n >= 64 || strlen(a) >= 64)
        return 64;
    for (int j = 0; j <= n; ++j)
        row[j] = j;
    for (const char *p = a; *p; ++p) {
        int diagonal = row[0];
        row[0] += 1;
        for (int j = 1; j <= n; ++j) {
            int substituted = diagonal + (*p != b[j - 1]);
            diagonal = row[j];
            int shortest = row[j] + 1 < row[j - 1] + 1 ? row[j] + 1 : row[j - 1] + 1;
            row[j] = substituted < shortest ? substituted : shortest;
        }
    }
    return row[n];
}

/* The option whose name is nearest `name` within a third of its length (at
 * least 2 edits), or NULL. */
static const cli_option *nearest_option(const cli_option *o, int n, const char *name)
{
    const cli_option *best = NULL;
    int best_distance = (int)strlen(name) / 3 > 2 ? (int)strlen(name) / 3 : 2;
    for (int i = 0; i < n; ++i) {
        int d = edit_distance(name, o[i].name);
        if (d <= best_distance && (!best || d < best_distance))
            best = &o[i], best_distance = d;
    }
    return best;
}

/* What getopt_long refused (it returned '?'), in one line: a known option
 * without its value, or an unknown (or ambiguous) one with the nearest valid
 * name; argv[optind - 1] is what was typed. */
static int refuse_option(const cli_command *cmd, int n, char **argv)
{
    const char *typed = optind > 0 ? argv[optind - 1] : "";
    int i = optopt ? index_of_code(cmd->options, n, optopt) : -1;
    if (i >= 0)
        return cli_failf(cmd->command, "--%s needs a value (%s; see 'gtlab %s --help')", cmd->options[i].name,
                         cmd->options[i].value ? cmd->options[i].value : "a value", cmd->command);
    if (optopt && optopt < 256)
        return cli_failf(cmd->command, "unknown option '-%c' (see 'gtlab %s --help')", optopt, cmd->command);
    char name[64];
    snprintf(name, sizeof name, "%.*s", (int)strcspn(typed + strspn(typed, "-"), "="), typed + strspn(typed, "-"));
    const cli_option *near = nearest_option(cmd->options, n, name);
    if (near)
        return cli_failf(cmd->command, "unknown option '--%s' (did you mean '--%s'?)", name, near->name);
    return cli_failf(cmd->command, "unknown option '--%s' (see 'gtlab %s --help')", name, cmd->command);
}

int cli_options_parse(const cli_command *cmd, void *const *dest, int argc, char **argv, int *status)
{
    struct option longs[MAX_OPTIONS + 2];
    char shorts[2 * MAX_OPTIONS + 2];
    int n = option_count(cmd->options);
    *status = EXIT_USER_ERROR;
    if (n > MAX_OPTIONS)
        return cli_failf(cmd->command, "more than %d options", MAX_OPTIONS), *status = EXIT_INTERNAL_ERROR, 1;
    build_longs(cmd->options, n, longs, shorts);
    for (int c; (c = getopt_long(argc, argv, shorts, longs, NULL)) != -1;) {
        if (c == 'h')
            return cli_options_print_help(cmd, dest), *status = EXIT_OK, 1;
        if (c == '?')
            return refuse_option(cmd, n, argv), 1;
        int i = index_of_code(cmd->options, n, c);
        if (i < 0)
            return cli_usage_error(cmd->command), 1;
        if (parse_value(&cmd->options[i], dest[i], optarg) != 0)
            return 1;
        note_input(&cmd->options[i], optarg);
    }
    if (cmd->arguments) {
        cli_arguments *args = dest[n];
        *args = (cli_arguments){argv + optind, argc - optind};
        for (int k = optind; k < argc; ++k)
            note_input(NULL, argv[k]);
    } else if (optind < argc) {
        return cli_failf(cmd->command, "unexpected argument '%s'", argv[optind]), 1;
    }
    if (check_required(cmd, dest, n) != 0 || check_outputs(cmd, dest, n) != 0)
        return 1;
    *status = EXIT_OK;
    return 0;
}

/* "--size N", "-o, --output DIR", "--lobe ggx|ggx-d|phong" for a choice
 * without a placeholder. */
static void format_option(const cli_option *o, char *out, size_t size)
{
    int k = o->short_name ? snprintf(out, size, "-%c, --%s", o->short_name, o->name) : snprintf(out, size, "--%s", o->name);
    if (o->value)
        snprintf(out + k, size - (size_t)k, " %s", o->value);
}

static void print_usage_line(const cli_command *cmd)
{
    printf("usage: gtlab %s", cmd->command);
    for (const cli_option *o = cmd->options; o->kind != CLI_KIND_END; ++o) {
        char text[96];
        format_option(o, text, sizeof text);
        if (o->short_name)
            snprintf(text, sizeof text, "-%c %s", o->short_name, o->value ? o->value : "");
        printf(o->required ? " %s" : " [%s]", text);
    }
    printf("%s%s\n\n%s\n\noptions:\n", cmd->arguments ? " " : "", cmd->arguments ? cmd->arguments : "",
           cmd->description);
}

/* The help text, continuation lines indented to the help column. */
static void print_help_text(const char *help)
{
    for (const char *p = help; *p; ++p) {
        putchar(*p);
        if (*p == '\n')
            printf("%*s", HELP_COLUMN, "");
    }
}

/* " (default X)" from the destination's value before parsing, unless the
 * help text already states its default or there is none. */
static void print_default(const cli_option *o, const void *dest)
{
    if (o->required || strstr(o->help, "default"))
        return;
    switch (o->kind) {
    case CLI_KIND_INT: printf(" (default %ld)", *(const long *)dest); break;
    case CLI_KIND_INT32: printf(" (default %d)", *(const int *)dest); break;
    case CLI_KIND_DOUBLE: printf(" (default %g)", *(const double *)dest); break;
    case CLI_KIND_FLOAT: printf(" (default %g)", (double)*(const float *)dest); break;
    case CLI_KIND_SWITCH: printf(" (default %s)", *(const int *)dest ? "on" : "off"); break;
    case CLI_KIND_STRING: if (*(const char *const *)dest) printf(" (default %s)", *(const char *const *)dest); break;
    case CLI_KIND_CHOICE: printf(" (default %s)", o->choice(*(const int *)dest)); break;
    default: break;
    }
}

void cli_options_print_help(const cli_command *cmd, void *const *dest)
{
    print_usage_line(cmd);
    for (int i = 0; cmd->options[i].kind != CLI_KIND_END; ++i) {
        const cli_option *o = &cmd->options[i];
        char text[96];
        format_option(o, text, sizeof text);
        if ((int)strlen(text) + 2 >= HELP_COLUMN)
            printf("  %s\n%*s", text, HELP_COLUMN, "");
        else
            printf("  %-*s", HELP_COLUMN - 2, text);
        print_help_text(o->help);
        print_default(o, dest[i]);
        putchar('\n');
    }
    printf("  -h, --help\n");
    if (cmd->epilogue)
        printf("\n%s\n", cmd->epilogue);
}

int cli_make_output_dir(const char *dir)
{
    if (mkdir(dir, 0777) != 0 && errno != EEXIST)
        return cli_failf(dir, "cannot create the folder: %s", strerror(errno));
    return 0;
}
