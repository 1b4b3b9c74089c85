/* libcufft.so.11 for cufinufft's CUDA 12 wheel on a CUDA 13 machine: the five functions it
   calls, forwarded to CUDA 13's libcufft.so.12 (same C API). */
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
static void *lib;
static void *sym(const char *name) {
    if (!lib) {
        lib = dlopen("libcufft.so.12", RTLD_NOW | RTLD_GLOBAL);
        if (!lib) { fprintf(stderr, "cufft forwarder: %s\n", dlerror()); abort(); }
    }
    void *f = dlsym(lib, name);
    if (!f) { fprintf(stderr, "cufft forwarder: no %s\n", name); abort(); }
    return f;
}
typedef int (*plan_many_t)(int *, int, int *, int *, int, int, int *, int, int, int, int);
typedef int (*set_stream_t)(int, void *);
typedef int (*exec_t)(int, void *, void *, int);
typedef int (*destroy_t)(int);
int cufftPlanMany(int *plan, int rank, int *n, int *inembed, int istride, int idist,
                  int *onembed, int ostride, int odist, int type, int batch) {
    return ((plan_many_t)sym("cufftPlanMany"))(plan, rank, n, inembed, istride, idist,
                                               onembed, ostride, odist, type, batch);
}
int cufftSetStream(int plan, void *stream) {
    return ((set_stream_t)sym("cufftSetStream"))(plan, stream);
}
int cufftExecC2C(int plan, void *i, void *o, int dir) {
    return ((exec_t)sym("cufftExecC2C"))(plan, i, o, dir);
}
int cufftExecZ2Z(int plan, void *i, void *o, int dir) {
    return ((exec_t)sym("cufftExecZ2Z"))(plan, i, o, dir);
}
int cufftDestroy(int plan) { return ((destroy_t)sym("cufftDestroy"))(plan); }
