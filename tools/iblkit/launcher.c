/* The `iblkit` a user runs: it starts the program (iblkit-program) with glibc's transparent huge
 * pages on, and is otherwise invisible (the same arguments, output and exit status).
 *
 * Fresh memory costs a page fault per 4 KiB page touched, about 3.5 ms per MB in a virtual
 * machine: huge pages made the default bake 0.94x as long, a 1024² bake 0.79x. A Debian kernel gives huge pages (one
 * fault per 2 MiB) only to memory marked for them, and glibc marks its heap only when its tunable
 * glibc.malloc.hugetlb says so as the program starts: too early for the program to set it itself,
 * and starting itself again costs a C++ program's start-up (15 ms), this program's 2-3 ms. A
 * GLIBC_TUNABLES that already names the tunable is left as it is. */
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define TUNABLE "glibc.malloc.hugetlb"

/* Beside this program (the build tree), then where it is installed (PROGRAM_FROM_BINDIR). */
static const char* const candidates[] = {"iblkit-program", PROGRAM_FROM_BINDIR};

static void addTunable(void) {
    const char* tunables = getenv("GLIBC_TUNABLES");
    if (tunables && strstr(tunables, TUNABLE)) return;
    char value[4096];
    int length = tunables && *tunables ? snprintf(value, sizeof value, "%s:" TUNABLE "=1", tunables)
                                       : snprintf(value, sizeof value, TUNABLE "=1");
    if (length < 0 || (size_t)length >= sizeof value) return; /* left as it is: small pages */
    setenv("GLIBC_TUNABLES", value, 1); /* where it fails, small pages too */
}

int main(int argc, char** argv) {
    (void)argc;
    char self[PATH_MAX];
    ssize_t length = readlink("/proc/self/exe", self, sizeof self - 1);
    if (length <= 0) {
        fprintf(stderr, "iblkit: cannot find its own path (/proc/self/exe): %s\n", strerror(errno));
        return 127;
    }
    self[length] = '\0';
    /* The program names this launcher where it writes a command for later (iblkit batch --slurm-script). */
    setenv("IBLKIT_LAUNCHER", self, 1);
    char* slash = strrchr(self, '/');
    slash[1] = '\0';
    addTunable();
    char program[PATH_MAX + 64];
    for (size_t i = 0; i < sizeof candidates / sizeof *candidates; ++i) {
        snprintf(program, sizeof program, "%s%s", self, candidates[i]);
        if (access(program, X_OK) == 0) {
            execv(program, argv);
            fprintf(stderr, "iblkit: cannot start %s: %s\n", program, strerror(errno));
            return 126;
        }
    }
    fprintf(stderr, "iblkit: the program is missing: no %s%s or %s%s\n", self, candidates[0], self, candidates[1]);
    return 127;
}
