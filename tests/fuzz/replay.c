/* replay.c: runs a fuzz target (checkpoint.c, api.c, stl.c) on files or on every file
 * of directories given as arguments, without libFuzzer: CTest's regression
 * run over tests/fuzz/corpus/. Prints how many inputs ran. */
#define _POSIX_C_SOURCE 200809L /* opendir */
#include <dirent.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static int run_file(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return perror(path), 1;
    unsigned char *b = NULL;
    size_t n = 0, cap = 0, got;
    do {
        if (n == cap && !(b = realloc(b, cap = 2 * cap + 4096)))
            return fclose(f), perror(path), 1;
        got = fread(b + n, 1, cap - n, f);
        n += got;
    } while (got);
    fclose(f);
    LLVMFuzzerTestOneInput(b, n);
    free(b);
    return 0;
}

int main(int argc, char **argv)
{
    size_t inputs = 0;
    for (int a = 1; a < argc; a++) {
        struct stat st;
        if (stat(argv[a], &st))
            return perror(argv[a]), 1;
        if (!S_ISDIR(st.st_mode)) {
            if (run_file(argv[a]))
                return 1;
            inputs++;
            continue;
        }
        DIR *d = opendir(argv[a]);
        if (!d)
            return perror(argv[a]), 1;
        for (struct dirent *e; (e = readdir(d));) {
            if (e->d_name[0] == '.')
                continue;
            char *path = malloc(strlen(argv[a]) + strlen(e->d_name) + 2);
            if (!path)
                return 1;
            sprintf(path, "%s/%s", argv[a], e->d_name);
            const int bad = run_file(path);
            free(path);
            if (bad)
                return closedir(d), 1;
            inputs++;
        }
        closedir(d);
    }
    printf("replay: %zu inputs ran without a fault\n", inputs);
    return inputs ? 0 : 1;
}
