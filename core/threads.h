/* How many worker threads a command uses when the user does not say: one
 * per processor OpenMP sees. Results never depend on it (docs/design.md,
 * determinism); only the command line asks and sets them. */
#ifndef GTLAB_CORE_THREADS_H
#define GTLAB_CORE_THREADS_H

int threads_default(void);
/* The number of threads later parallel passes of this process use. */
void threads_set(int count);

#endif
