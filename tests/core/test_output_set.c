/* core/files/output_set.c with core/files/atomic_file.c: the files of a set are kept
 * together (commit) or not at all (abort, a signal), what they replaced comes
 * back, no hidden temporary or backup stays, and a destination that is not a
 * regular file is refused. */
#define _POSIX_C_SOURCE 200809L
#include "core/files/atomic_file.h"
#include "core/files/output_set.h"
#include "tests/check.h"

#include <dirent.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

static char dir[2048];

static const char *in_dir(const char *name)
{
    static char paths[4][4096];
    static int next;
    char *p = paths[next++ % 4];
    snprintf(p, 4096, "%s/%s", dir, name);
    return p;
}

/* The file's text ("" if absent). */
static const char *text_of(const char *name)
{
    static char text[64];
    text[0] = '\0';
    FILE *f = fopen(in_dir(name), "r");
    if (f) {
        size_t n = fread(text, 1, sizeof text - 1, f);
        text[n] = '\0';
        fclose(f);
    }
    return text;
}

static int exists(const char *name)
{
    struct stat st;
    return stat(in_dir(name), &st) == 0;
}

/* Hidden entries (temporaries, backups) in the folder. */
static int hidden_files(void)
{
    int n = 0;
    DIR *d = opendir(dir);
    for (struct dirent *x; d && (x = readdir(d));)
        n += x->d_name[0] == '.' && strcmp(x->d_name, ".") != 0 && strcmp(x->d_name, "..") != 0;
    if (d)
        closedir(d);
    return n;
}

static void fresh_folder(const char *name)
{
    snprintf(dir, sizeof dir, "%s/output_set_%s", check_tmp_dir(), name);
    mkdir(dir, 0755);
    const char *names[] = {"a", "b", "c"};
    for (int i = 0; i < 3; ++i)
        remove(in_dir(names[i]));
    gt_error e;
    CHECK(atomic_write_text(in_dir("b"), "old", &e) == 0); /* outside a set: a plain write */
    mkdir(in_dir("c"), 0755);                               /* a destination that cannot be written */
}

static void test_commit_keeps_all(void)
{
    fresh_folder("commit");
    gt_error e;
    output_set_begin();
    CHECK(atomic_write_text(in_dir("a"), "new a", &e) == 0);
    CHECK(atomic_write_text(in_dir("b"), "new b", &e) == 0);
    CHECK(strcmp(text_of("a"), "new a") == 0); /* in place at once: later steps read it */
    CHECK(output_set_commit(&e) == 0);
    CHECK(strcmp(text_of("a"), "new a") == 0 && strcmp(text_of("b"), "new b") == 0);
    CHECK(hidden_files() == 0);
}

/* The third file fails: the first two go, b's previous text comes back. */
static void test_failure_at_a_later_file_leaves_none(void)
{
    fresh_folder("abort");
    gt_error e;
    output_set_begin();
    CHECK(atomic_write_text(in_dir("a"), "new a", &e) == 0);
    CHECK(atomic_write_text(in_dir("b"), "new b", &e) == 0);
    CHECK(atomic_write_text(in_dir("b"), "newer b", &e) == 0);
    CHECK(atomic_write_text(in_dir("c"), "c", &e) != 0);
    output_set_abort();
    CHECK(!exists("a"));
    CHECK(strcmp(text_of("b"), "old") == 0);
    CHECK(hidden_files() == 0);
    CHECK(!output_set_is_open());
}

/* SIGTERM while a file is committed and another half written: the child
 * exits 128 + 15 and leaves the folder as it was. */
static void test_signal_leaves_nothing(void)
{
    fresh_folder("signal");
    pid_t child = fork();
    if (child == 0) {
        gt_error e;
        atomic_file half;
        output_set_install_signal_handlers();
        output_set_begin();
        if (atomic_write_text(in_dir("a"), "new a", &e) != 0 || atomic_write_text(in_dir("b"), "new b", &e) != 0 ||
            atomic_file_begin(&half, in_dir("d"), &e) != 0)
            _exit(1);
        raise(SIGTERM);
        _exit(2);
    }
    int status = 0;
    CHECK(waitpid(child, &status, 0) == child);
    CHECK(WIFEXITED(status) && WEXITSTATUS(status) == 128 + SIGTERM);
    CHECK(!exists("a") && !exists("d"));
    CHECK(strcmp(text_of("b"), "old") == 0);
    CHECK(hidden_files() == 0);
}

static void test_device_refused(void)
{
    gt_error e;
    atomic_file f;
    struct stat st;
    CHECK(stat("/dev/null", &st) == 0 && S_ISCHR(st.st_mode));
    CHECK(atomic_file_begin(&f, "/dev/null", &e) != 0);
    CHECK(strstr(e.message, "not a regular file") != NULL);
    CHECK(stat("/dev/null", &st) == 0 && S_ISCHR(st.st_mode));
}

int main(void)
{
    test_commit_keeps_all();
    test_failure_at_a_later_file_leaves_none();
    test_signal_leaves_nothing();
    test_device_refused();
    return check_report("test_output_set");
}
