/* Output sets and the signal handler that cleans up after them; see
 * output_set.h. */
#define _POSIX_C_SOURCE 200809L
#include "core/files/output_set.h"

#include <errno.h>
#include <pthread.h>
#include <signal.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

enum { TEMPORARY_SLOTS = 256, CHUNK = 256, CHUNKS = 256 };

/* A file the open set put in place; backup_path NULL: nothing was there. */
typedef struct {
    char *final_path, *backup_path;
} set_entry;

/* Temporaries that exist now (NULL: free slot). */
static _Atomic(char *) temporaries[TEMPORARY_SLOTS];
/* The open set's files, in chunks that never move (the handler reads them). */
static set_entry *chunks[CHUNKS];
static atomic_int entry_count;
static atomic_int set_open;
static pthread_mutex_t entries_lock = PTHREAD_MUTEX_INITIALIZER;

static set_entry *entry_at(int i)
{
    return &chunks[i / CHUNK][i % CHUNK];
}

/* "<dir>/.<name>.<kind>-<pid>", malloc'd. */
static char *hidden_sibling(const char *path, const char *kind)
{
    const char *slash = strrchr(path, '/');
    int dir_len = slash ? (int)(slash - path + 1) : 0;
    size_t size = strlen(path) + strlen(kind) + 32;
    char *name = malloc(size);
    if (name)
        snprintf(name, size, "%.*s.%s.%s-%ld", dir_len, path, path + dir_len, kind, (long)getpid());
    return name;
}

void output_set_temporary_created(const char *temp_path)
{
    char *copy = strdup(temp_path);
    for (int i = 0; copy && i < TEMPORARY_SLOTS; ++i) {
        char *expected = NULL;
        if (atomic_compare_exchange_strong(&temporaries[i], &expected, copy))
            return;
    }
    free(copy); /* untracked: only an interruption would leave it */
}

void output_set_temporary_gone(const char *temp_path)
{
    for (int i = 0; i < TEMPORARY_SLOTS; ++i) {
        char *p = atomic_load(&temporaries[i]);
        if (p && strcmp(p, temp_path) == 0 && atomic_compare_exchange_strong(&temporaries[i], &p, NULL)) {
            free(p);
            return;
        }
    }
}

/* Undoes the set's renames, newest first: what each file replaced goes back,
 * a file that replaced nothing is removed. Only unlink and rename: the
 * signal handler calls it too. */
static void roll_back(void)
{
    for (int i = atomic_load(&entry_count) - 1; i >= 0; --i) {
        const set_entry *s = entry_at(i);
        if (s->backup_path)
            rename(s->backup_path, s->final_path);
        else
            unlink(s->final_path);
    }
}

static void forget_entries(void)
{
    int n = atomic_exchange(&entry_count, 0);
    for (int i = 0; i < n; ++i) {
        free(entry_at(i)->final_path);
        free(entry_at(i)->backup_path);
    }
}

static int in_set(const char *final_path)
{
    for (int i = 0; i < atomic_load(&entry_count); ++i)
        if (strcmp(entry_at(i)->final_path, final_path) == 0)
            return 1;
    return 0;
}

/* Appends (final, backup) to the set; the entry is whole before the count
 * publishes it. */
static int record(const char *final_path, char *backup_path)
{
    int n = atomic_load(&entry_count);
    if (n == CHUNK * CHUNKS || (!chunks[n / CHUNK] && !(chunks[n / CHUNK] = calloc(CHUNK, sizeof(set_entry)))))
        return -1;
    set_entry *s = entry_at(n);
    s->final_path = strdup(final_path);
    s->backup_path = backup_path;
    if (!s->final_path)
        return -1;
    atomic_store(&entry_count, n + 1);
    return 0;
}

/* Keeps the existing final_path as a hidden hard link (or, where the file
 * system has none, by renaming it aside); the backup's name, or NULL with
 * errno set. */
static char *keep_backup(const char *final_path)
{
    char *backup = hidden_sibling(final_path, "bak");
    if (!backup)
        return NULL;
    unlink(backup); /* a stale one of an earlier process with this pid */
    if (link(final_path, backup) == 0 || rename(final_path, backup) == 0)
        return backup;
    int err = errno;
    free(backup);
    errno = err;
    return NULL;
}

static int rename_in_set(const char *temp_path, const char *final_path)
{
    struct stat st;
    int first = !in_set(final_path), existed = lstat(final_path, &st) == 0;
    char *backup = first && existed ? keep_backup(final_path) : NULL;
    if (first && existed && !backup)
        return -1;
    if (rename(temp_path, final_path) != 0) {
        int err = errno;
        if (backup && rename(backup, final_path) != 0)
            unlink(backup);
        free(backup);
        errno = err;
        return -1;
    }
    if (first && record(final_path, backup) != 0) {
        free(backup);
        errno = ENOMEM;
        return -1;
    }
    return 0;
}

int output_set_rename_into_place(const char *temp_path, const char *final_path)
{
    if (!atomic_load(&set_open))
        return rename(temp_path, final_path);
    pthread_mutex_lock(&entries_lock);
    int rc = rename_in_set(temp_path, final_path);
    pthread_mutex_unlock(&entries_lock);
    return rc;
}

int output_set_is_open(void)
{
    return atomic_load(&set_open);
}

void output_set_begin(void)
{
    if (atomic_load(&set_open))
        output_set_commit(NULL);
    atomic_store(&set_open, 1);
}

int output_set_commit(gt_error *e)
{
    pthread_mutex_lock(&entries_lock);
    int rc = 0;
    for (int i = 0; i < atomic_load(&entry_count); ++i) {
        const char *backup = entry_at(i)->backup_path;
        if (backup && unlink(backup) != 0 && errno != ENOENT && rc == 0)
            rc = e ? gt_error_set(e, backup, "cannot remove this backup of the previous output: %s", strerror(errno))
                   : -1;
    }
    atomic_store(&set_open, 0);
    forget_entries();
    pthread_mutex_unlock(&entries_lock);
    return rc;
}

void output_set_abort(void)
{
    pthread_mutex_lock(&entries_lock);
    atomic_store(&set_open, 0);
    roll_back();
    forget_entries();
    pthread_mutex_unlock(&entries_lock);
}

/* The note the handler writes: two buffers, the one published in use. */
static char notes[2][1024];
static atomic_int note_in_use = -1;

void output_set_interrupt_note(const char *line)
{
    if (!line) {
        atomic_store(&note_in_use, -1);
        return;
    }
    int next = atomic_load(&note_in_use) == 0 ? 1 : 0;
    snprintf(notes[next], sizeof notes[next], "%s", line);
    atomic_store(&note_in_use, next);
}

static void on_signal(int signal_number)
{
    const int note = atomic_load(&note_in_use);
    if (note >= 0 && write(STDERR_FILENO, notes[note], strlen(notes[note])) < 0) {
        /* nothing more to say where stderr is gone */
    }
    for (int i = 0; i < TEMPORARY_SLOTS; ++i) {
        char *p = atomic_load(&temporaries[i]);
        if (p)
            unlink(p);
    }
    if (atomic_load(&set_open))
        roll_back();
    _exit(128 + signal_number);
}

void output_set_install_signal_handlers(void)
{
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sigemptyset(&sa.sa_mask);
    const int signals[3] = {SIGINT, SIGTERM, SIGHUP};
    for (int i = 0; i < 3; ++i) {
        struct sigaction old;
        /* A signal the parent ignores stays ignored (a shell's background
         * job ignores SIGINT; nohup ignores SIGHUP). */
        if (sigaction(signals[i], NULL, &old) == 0 && old.sa_handler != SIG_IGN)
            sigaction(signals[i], &sa, NULL);
    }
}
