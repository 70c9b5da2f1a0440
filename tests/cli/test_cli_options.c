/* cli/cli_options: the declarative option table every subcommand parses
 * with. Values land in their destinations with their types; a value out of
 * range, an unknown option or value, a stray or missing argument each stop
 * the subcommand with exit status 1 and one line on stderr naming the
 * option; --help stops it with status 0 and prints every option with the
 * defaults read from the destinations. */
#define _GNU_SOURCE
#include "cli/cli.h"
#include "cli/cli_options.h"
#include "tests/check.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static const char *colour_name(int i) { return (const char *[]){"red", "green", "blue"}[i]; }
static const char *side_name(int i) { return i ? "right" : "left"; }

/* "N|inf": a count, or -1 for inf. */
static int parse_count(void *dest, const char *text)
{
    if (strcmp(text, "inf") == 0)
        return *(long *)dest = -1, 0;
    return cli_parse_int("--bounces", text, 0, 100, dest);
}

static const cli_option options[] = {
    CLI_INT("size", "N", 2, 256, "entries per axis"),
    CLI_INT32("count", "N", 1, 10, "a small count"),
    CLI_DOUBLE("scale", "X", 0.5, 2.0, "a scale"),
    CLI_FLOAT("radius", "R", 1e-3, 10, "a radius"),
    CLI_FLAG("json", "print JSON"),
    CLI_STRING("name", "S", "a name"),
    CLI_CHOICE("colour", "C", colour_name, 3, "red, green or blue"),
    CLI_CHOICE("side", "D", side_name, 2, "left or right"),
    CLI_SWITCH("denoise", "the denoiser"),
    CLI_CUSTOM("bounces", "N|inf", parse_count, "bounces, or inf (default 4)"),
    CLI_OUTPUT("DIR", 1, "output folder"),
    CLI_END};
static const cli_command command = {"test cmd", "A command for the test.", options, NULL, NULL};

typedef struct {
    long size;
    int count;
    double scale;
    float radius;
    int json;
    const char *name;
    int colour, side, denoise;
    long bounces;
    const char *dir;
} values;

static const values defaults = {32, 3, 1.0, 0.25f, 0, "plain", 1, 0, 1, 4, NULL};

/* Parses the words (argv[0] is the subcommand) with stdout and stderr caught
 * in out and err; returns what cli_options_parse returned. */
static int parse(values *v, int *status, char *out, char *err, size_t size, const char *words)
{
    char buffer[512], *argv[32];
    int argc = 0;
    snprintf(buffer, sizeof buffer, "cmd %s", words);
    for (char *w = strtok(buffer, " "); w && argc < 31; w = strtok(NULL, " "))
        argv[argc++] = w;
    argv[argc] = NULL;
    *v = defaults;
    fflush(stdout);
    fflush(stderr);
    FILE *fo = tmpfile(), *fe = tmpfile();
    int saved_out = dup(1), saved_err = dup(2);
    dup2(fileno(fo), 1);
    dup2(fileno(fe), 2);
    cli_reset_getopt();
    int rc = cli_options_parse(&command, (void *[]){&v->size, &v->count, &v->scale, &v->radius, &v->json, &v->name,
                               &v->colour, &v->side, &v->denoise, &v->bounces, &v->dir}, argc, argv, status);
    fflush(stdout);
    fflush(stderr);
    dup2(saved_out, 1);
    dup2(saved_err, 2);
    close(saved_out);
    close(saved_err);
    FILE *files[2] = {fo, fe};
    char *texts[2] = {out, err};
    for (int i = 0; i < 2; ++i) {
        rewind(files[i]);
        size_t n = fread(texts[i], 1, size - 1, files[i]);
        texts[i][n] = '\0';
        fclose(files[i]);
    }
    return rc;
}

/* The words must be refused: status 1, exactly one line on stderr holding expected. */
static void check_refused(const char *words, const char *expected)
{
    values v;
    int status = -1;
    char out[8192], err[8192];
    int rc = parse(&v, &status, out, err, sizeof out, words);
    const char *newline = strchr(err, '\n');
    CHECK_MSG(rc == 1 && status == EXIT_USER_ERROR, "'%s': rc %d, status %d", words, rc, status);
    CHECK_MSG(newline && newline[1] == '\0' && strstr(err, expected), "'%s': stderr '%s', expected '%s'", words, err,
              expected);
}

static void test_values_reach_their_destinations(void)
{
    values v;
    int status = -1;
    char out[8192], err[8192];
    CHECK(parse(&v, &status, out, err, sizeof out, "--size 64 --count 10 --scale 0.5 --radius 2.5 --json --name x "
                "--colour blue --side right --denoise off --bounces inf -o d") == 0);
    CHECK(status == EXIT_OK && err[0] == '\0' && out[0] == '\0');
    CHECK(v.size == 64 && v.count == 10 && v.scale == 0.5 && v.radius == 2.5f && v.json == 1);
    CHECK(strcmp(v.name, "x") == 0 && v.colour == 2 && v.side == 1 && v.denoise == 0 && v.bounces == -1);
    CHECK(strcmp(v.dir, "d") == 0);
    /* Untouched options keep their defaults; --output=VALUE and --output work as -o. */
    CHECK(parse(&v, &status, out, err, sizeof out, "--output=e --bounces 7") == 0);
    CHECK(v.size == 32 && v.count == 3 && v.colour == 1 && v.denoise == 1 && v.bounces == 7 && strcmp(v.dir, "e") == 0);
    /* A float is the rounded double: 0.1 as a float, not 0.1 as a double. */
    CHECK(parse(&v, &status, out, err, sizeof out, "--radius 0.1 -o d") == 0 && v.radius == 0.1f);
}

static void test_bad_values_are_refused_with_one_line(void)
{
    check_refused("--size 1 -o d", "--size: 1 is out of range");
    check_refused("--size 257 -o d", "--size: 257 is out of range");
    check_refused("--size many -o d", "--size: 'many' is not a whole number");
    check_refused("--count 11 -o d", "--count: 11 is out of range");
    check_refused("--scale 2.5 -o d", "--scale: ");
    check_refused("--radius 0 -o d", "--radius: ");
    check_refused("--colour pink -o d", "--colour: 'pink' is not red, green or blue");
    check_refused("--side up -o d", "--side: 'up' is neither left nor right");
    check_refused("--denoise maybe -o d", "--denoise: 'maybe' is neither on nor off");
    check_refused("--bounces 101 -o d", "--bounces: 101 is out of range");
}

static void test_usage_errors(void)
{
    check_refused("--colour-scheme red -o d", "test cmd: unknown option '--colour-scheme' (see 'gtlab test cmd --help')");
    check_refused("--sizee 8 -o d", "test cmd: unknown option '--sizee' (did you mean '--size'?)");
    check_refused("--radus=2 -o d", "test cmd: unknown option '--radus' (did you mean '--radius'?)");
    check_refused("--bouncez 3 -o d", "test cmd: unknown option '--bouncez' (did you mean '--bounces'?)");
    check_refused("-x -o d", "test cmd: unknown option '-x' (see 'gtlab test cmd --help')");
    check_refused("--size", "test cmd: --size needs a value (N; see 'gtlab test cmd --help')");
    check_refused("-o", "test cmd: --output needs a value (DIR; see 'gtlab test cmd --help')");
    check_refused("-o d extra", "test cmd: unexpected argument 'extra'");
    check_refused("--size 8", "test cmd: -o/--output DIR is required");
}

static void test_help_lists_options_and_defaults(void)
{
    values v;
    int status = -1;
    char out[8192], err[8192];
    CHECK(parse(&v, &status, out, err, sizeof out, "--size 99 --help") == 1);
    CHECK(status == EXIT_OK && err[0] == '\0');
    CHECK_MSG(strncmp(out, "usage: gtlab test cmd", 21) == 0, "help starts '%.40s'", out);
    const char *expected[] = {"--size N", "(default 99)", "--count N", "(default 3)", "(default 1)", "(default 0.25)",
                              "--json", "(default plain)", "(default green)", "(default left)", "(default on)",
                              "bounces, or inf (default 4)", "-o, --output DIR", "-h, --help", "A command for the test."};
    for (size_t i = 0; i < sizeof expected / sizeof expected[0]; ++i)
        CHECK_MSG(strstr(out, expected[i]), "help lacks '%s'", expected[i]);
    /* A help text stating its own default gets no second one; a required option none. */
    CHECK(!strstr(out, "(default 4) (default"));
    CHECK(!strstr(out, "output folder (default"));
}

static void test_positional_arguments(void)
{
    static const cli_option none[] = {CLI_FLAG("json", "print JSON"), CLI_END};
    static const cli_command files = {"files", "Files.", none, "A B", NULL};
    char *argv[] = {"files", "a", "--json", "b", NULL};
    int json = 0, status = -1;
    cli_arguments args;
    cli_reset_getopt();
    CHECK(cli_options_parse(&files, (void *[]){&json, &args}, 4, argv, &status) == 0 && status == EXIT_OK);
    CHECK(json == 1 && args.count == 2 && strcmp(args.values[0], "a") == 0 && strcmp(args.values[1], "b") == 0);
}

static void test_list_option_repeats_up_to_its_capacity(void)
{
    const char *items[2];
    cli_list list = {items, 0, 2, "--data"};
    CHECK(cli_list_add(&list, "a") == 0 && cli_list_add(&list, "b") == 0 && list.count == 2);
    fflush(stderr);
    int saved = dup(2);
    FILE *null = fopen("/dev/null", "w");
    dup2(fileno(null), 2);
    int rc = cli_list_add(&list, "c");
    fflush(stderr);
    dup2(saved, 2);
    close(saved);
    fclose(null);
    CHECK(rc == -1 && list.count == 2 && strcmp(items[1], "b") == 0);
}

int main(void)
{
    test_values_reach_their_destinations();
    test_bad_values_are_refused_with_one_line();
    test_usage_errors();
    test_help_lists_options_and_defaults();
    test_positional_arguments();
    test_list_option_repeats_up_to_its_capacity();
    return check_report("cli_options");
}
