/* The cost of de Carpentier's Newton step (Decima, SIGGRAPH 2017: "+87%
 * cycles") measured in C: x86-64 instructions of the two functions a
 * shader would hard-code, counted from the disassembly of this very binary
 * (objdump), and time per call over a large array of configurations. Used
 * by `gtlab bench sphere-light` and the sphere-light stage of `gtlab all`. */
#ifndef GTLAB_CLI_BENCH_SPHERE_LIGHT_H
#define GTLAB_CLI_BENCH_SPHERE_LIGHT_H

typedef struct {
    int instructions[2];    /* Karis (0 steps), Decima (1 step); -1 if objdump is unavailable */
    int calls[2];           /* call instructions inside them (0: straight code) */
    double ns_per_call[2];  /* best of the passes, one thread */
    long count;             /* configurations per pass */
    double share_early_out; /* R inside the light: both return 1 at once */
} sphere_cost;

void sphere_cost_measure(long count, int repeats, sphere_cost *out);

#endif
