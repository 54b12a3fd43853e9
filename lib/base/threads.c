/* threads.c: the world's own worker threads, and running a loop over
 * particles on them (dm_parallel).
 *
 * A world that steps on n > 1 threads starts n - 1 workers the first time a
 * loop is shared out, and keeps them until it is destroyed or its thread
 * count changes. A loop is split into one range of particles per thread, the
 * same ranges for every loop of a step (split so that the longest loop of
 * the last steps takes each range the same time: dm_balance): thread t (the
 * caller is 0) takes range t first, so that the particles a thread drifts
 * are the ones whose contacts and sums it computes next, in its own core's
 * cache; then it takes any range no thread has taken yet, so that a worker
 * that has not woken up in time delays nothing. Each range writes its
 * results at its own index, whichever thread ran it, and no sum depends on
 * the ranges, so results never depend on who did what. A thread that waits
 * (a worker for the next loop, the caller for the last range) spins for a
 * short while and then sleeps on a condition variable, so that the library
 * does not take a busy machine's cores from its other work. And as the world
 * steps, the pool keeps measuring whether sharing out pays (dm_adapt): on a
 * machine whose other work leaves it no second core, the loops run on the
 * calling thread alone. docs/design.md, Threads, says why, with the
 * measurements.
 *
 * Without threads (DEMILL_HAVE_THREADS undefined: built with
 * -DDEMILL_OPENMP=OFF or without POSIX threads) a world has one thread and
 * dm_parallel() runs its loop as one range. */
#define _GNU_SOURCE /* sched_getaffinity, CPU_COUNT */

#include <stdlib.h>
#include <string.h>

#include "base/threads.h"

/* Fewer particles than this per range are not worth sharing out. */
#define MIN_PER_RANGE 512

/* Where range t of [0, n) in `ranges` equal parts starts. */
static uint32_t equal_cut(uint32_t n, int t, int ranges)
{
    return (uint32_t)((uint64_t)n * (uint64_t)t / (uint64_t)ranges);
}

#ifdef DEMILL_HAVE_THREADS
#include <pthread.h>
#include <sched.h>
#include <signal.h>
#include <stdatomic.h>
#include <time.h>
#include <unistd.h>

/* How long a waiting thread spins before it sleeps: longer than the serial
 * work between two loops of a step on an idle machine, short against the
 * system's time slice (docs/design.md, Threads). */
#define SPIN_NS 50000

#if defined(__x86_64__) || defined(__i386__)
#define RELAX() __builtin_ia32_pause()
#elif defined(__aarch64__)
#define RELAX() __asm__ __volatile__("yield")
#else
#define RELAX() ((void)0)
#endif

/* One thread or several, measured as the world steps (docs/design.md,
 * Threads): the time spent in the loops (dm_parallel) per step, over PROBE
 * steps with the loops shared out and PROBE steps with each loop one range
 * on the calling thread (the same results: no sum depends on the ranges);
 * then the faster way is kept for `hold` steps, which double, up to
 * HOLD_MAX, each time the same way wins again. A hold ends early, and the
 * next comparison starts, when the way kept has become SLOWER times slower
 * than when it won, over PROBE steps: the machine's load has changed. */
#define PROBE 200
#define HOLD_MIN 1000
#define HOLD_MAX 32000
#define SLOWER 1.5

typedef struct dm_adapt {
    uint64_t step;      /* the world's steps when a loop last ran */
    bool solo;          /* this step's loops are one range each */
    bool won_solo;      /* one range won the last comparison */
    bool solo_first;    /* the next comparison probes one range first */
    int phase;          /* 0: holding, 1: first probe, 2: second probe */
    uint32_t left;      /* steps left in the phase */
    uint32_t hold;      /* steps the last winner is kept */
    double spent;       /* ns in the loops in this phase */
    double per_step[2]; /* ns per step in the last probes: shared, one range */
} dm_adapt;

/* Where the ranges of a loop over [0, n) split (docs/design.md, Threads):
 * equal parts at first; then after each step that shared its loops out,
 * each cut moves a STEER-th of the way to where the step's longest loop
 * (the contacts, in a mill) would have taken every range the same time,
 * the time of each range taken as spread evenly over its particles. A
 * range keeps at least MIN_PER_RANGE / 2 particles. The cuts change only
 * between steps, so that every loop of a step has the same ranges, as
 * DM_FORCES_DEFER needs; no result depends on them. */
#define STEER 4

typedef struct dm_balance {
    uint32_t n;  /* the length of the loops the cuts are for; 0: none yet */
    int ranges;  /* and their number of ranges */
    uint32_t cut[DM_MAX_THREADS + 1];
    double ns[DM_MAX_THREADS]; /* the last loop's time per range */
    double longest;            /* the step's longest loop so far: its slowest range's time, */
    uint32_t longest_n;        /* its length and number of ranges, */
    int longest_ranges;
    double longest_ns[DM_MAX_THREADS]; /* and its time per range */
} dm_balance;

/* Range t of `ranges` of a loop over [0, n). */
static void range_of(const dm_balance *b, uint32_t n, int t, int ranges, uint32_t *begin,
                     uint32_t *end)
{
    if (b->n == n && b->ranges == ranges) {
        *begin = b->cut[t];
        *end = b->cut[t + 1];
    } else {
        *begin = equal_cut(n, t, ranges);
        *end = equal_cut(n, t + 1, ranges);
    }
}

/* A loop of `ranges` ranges over [0, n) has run, its times in b->ns: kept
 * if it is the step's longest so far. */
static void balance_note(dm_balance *b, uint32_t n, int ranges)
{
    double slowest = 0.0;
    for (int t = 0; t < ranges; t++)
        slowest = b->ns[t] > slowest ? b->ns[t] : slowest;
    if (slowest <= b->longest)
        return;
    b->longest = slowest;
    b->longest_n = n;
    b->longest_ranges = ranges;
    memcpy(b->longest_ns, b->ns, (size_t)ranges * sizeof *b->ns);
}

/* A new step: the cuts moved after the last step's longest loop. */
static void balance_step(dm_balance *b)
{
    const uint32_t n = b->longest_n;
    const int R = b->longest_ranges;
    const double *ns = b->longest_ns;
    b->longest = 0.0;
    b->longest_ranges = 0;
    if (R < 2)
        return;
    if (b->n != n || b->ranges != R) {
        for (int t = 0; t <= R; t++)
            b->cut[t] = equal_cut(n, t, R);
        b->n = n;
        b->ranges = R;
    }
    double total = 0.0;
    for (int t = 0; t < R; t++)
        total += ns[t];
    if (!(total > 0.0))
        return;
    /* cut k where the time before it would be k / R of the whole */
    uint32_t cut[DM_MAX_THREADS + 1];
    double before = 0.0; /* the time of ranges 0 .. t - 1 */
    int t = 0;
    for (int k = 1; k < R; k++) {
        const double want = total * k / R;
        while (t + 1 < R && before + ns[t] < want)
            before += ns[t++];
        const double part = ns[t] > 0.0 ? (want - before) / ns[t] : 0.5;
        const double at = b->cut[t] + part * (double)(b->cut[t + 1] - b->cut[t]);
        cut[k] = (uint32_t)((double)b->cut[k] + (at - (double)b->cut[k]) / STEER);
    }
    const uint32_t least = MIN_PER_RANGE / 2;
    cut[0] = 0;
    for (int k = 1; k < R; k++) { /* each range at least `least` long, from both ends */
        const uint32_t lo = cut[k - 1] + least, hi = n - (uint32_t)(R - k) * least;
        cut[k] = cut[k] < lo ? lo : cut[k] > hi ? hi : cut[k];
    }
    memcpy(b->cut + 1, cut + 1, (size_t)(R - 1) * sizeof *cut);
}

/* A new step: counts the one before in the phase, and at the end of the
 * phase starts the next. */
static void next_step(dm_adapt *a, uint64_t step)
{
    a->step = step;
    if (--a->left && a->phase == 0 && (a->hold - a->left) % PROBE == 0) {
        if (a->per_step[a->solo] > 0.0 && a->spent > SLOWER * PROBE * a->per_step[a->solo]) {
            a->hold = HOLD_MIN / 2; /* (doubled below if the same way wins) */
            a->left = 0;
        }
        a->spent = 0.0;
    }
    if (a->left)
        return;
    if (a->phase)
        a->per_step[a->solo] = a->spent / PROBE;
    if (a->phase == 0) {
        a->phase = 1;
        a->solo = a->solo_first;
        a->solo_first = !a->solo_first;
        a->left = PROBE;
    } else if (a->phase == 1) {
        a->phase = 2;
        a->solo = !a->solo;
        a->left = PROBE;
    } else {
        const bool solo = a->per_step[1] < a->per_step[0];
        a->hold = solo != a->won_solo ? HOLD_MIN : a->hold < HOLD_MAX / 2 ? 2 * a->hold : HOLD_MAX;
        a->won_solo = a->solo = solo;
        a->phase = 0;
        a->left = a->hold;
    }
    a->spent = 0.0;
}

/* The current loop ("job") is published in one word, claim: the job's
 * number (bits 63..32) and its number of ranges (31..0). Range r of job j
 * is free while taken[r] is j - 1 (the caller sets it so before it
 * publishes the job), and a thread takes it by a compare-and-swap to j: so
 * a thread that wakes late, still seeing an older job, can never take a
 * range of a job that has ended or run one job's ranges with another's
 * function (the job's other fields do not change until its last range is
 * done, and a range taken is not done yet). */
typedef struct dm_worker {
    dm_pool *pool;
    int self; /* its thread's number: 1 .. workers (the caller is 0) */
} dm_worker;

struct dm_pool {
    int workers;
    pthread_t *tid;
    dm_worker *who;
    _Atomic uint32_t taken[DM_MAX_THREADS];
    pthread_mutex_t lock;
    pthread_cond_t wake, done; /* workers wait on wake, the caller on done */
    atomic_int sleepers;       /* workers asleep on wake, or about to be */
    atomic_int caller_asleep;
    atomic_bool stop;
    _Atomic uint64_t claim;
    atomic_int left; /* ranges of the job not yet done */
    uint32_t job;    /* the caller's count of jobs */
    demill_world *w;
    dm_range_fn fn;
    void *arg;
    uint32_t n;
    dm_adapt adapt;
    dm_balance balance;
};

static double ns_now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return 1e9 * (double)t.tv_sec + (double)t.tv_nsec;
}

static uint32_t job_of(uint64_t claim)
{
    return (uint32_t)(claim >> 32);
}

/* Takes a free range of job `job` for thread `self`, its own first
 * (range self × ranges / threads), then the ones after it, and gives the
 * job's number of ranges; -1 when none is left or the job has ended. */
static int take(dm_pool *p, uint32_t job, int self, int *ranges)
{
    const uint64_t c = atomic_load_explicit(&p->claim, memory_order_acquire);
    const uint32_t count = (uint32_t)c;
    if (job_of(c) != job)
        return -1;
    const uint32_t first = (uint32_t)self * count / (uint32_t)(p->workers + 1);
    for (uint32_t k = 0; k < count; k++) {
        const uint32_t r = (first + k) % count;
        uint32_t free = job - 1;
        if (atomic_load_explicit(&p->taken[r], memory_order_relaxed) == free &&
            atomic_compare_exchange_strong_explicit(&p->taken[r], &free, job,
                                                    memory_order_acquire, memory_order_relaxed)) {
            *ranges = (int)count;
            return (int)r;
        }
    }
    return -1;
}

/* Runs ranges of job `job` on thread `self` until none is left; true if
 * this thread finished the job's last range. */
static bool work(dm_pool *p, uint32_t job, int self)
{
    bool last = false;
    int t, ranges;
    while ((t = take(p, job, self, &ranges)) >= 0) {
        uint32_t begin, end;
        range_of(&p->balance, p->n, t, ranges, &begin, &end);
        const double start = ns_now();
        p->fn(p->w, p->arg, t, begin, end);
        p->balance.ns[t] = ns_now() - start;
        last = atomic_fetch_sub(&p->left, 1) == 1; /* seq_cst: see run_job */
    }
    return last;
}

/* Whether the worker that last saw job `seen` has none new, and whether the
 * caller still has ranges to wait for: what the threads spin on. */
static bool no_new_job(dm_pool *p, uint32_t seen)
{
    return job_of(atomic_load_explicit(&p->claim, memory_order_acquire)) == seen;
}

static bool ranges_left(dm_pool *p, uint32_t unused)
{
    (void)unused;
    return atomic_load_explicit(&p->left, memory_order_acquire) != 0;
}

/* Spins while waiting(p, x), for at most SPIN_NS; false if it still is. */
static bool spin(dm_pool *p, bool (*waiting)(dm_pool *, uint32_t), uint32_t x)
{
    if (!waiting(p, x))
        return true;
    const double until = ns_now() + SPIN_NS;
    for (unsigned k = 1; waiting(p, x); k++) {
        if (k % 64 == 0 && ns_now() > until)
            return false;
        RELAX();
    }
    return true;
}

/* A worker: waits for a job other than the last it saw, spinning and then
 * asleep, takes its ranges, and wakes the caller if it finished the job
 * while the caller slept. */
static void *worker(void *arg)
{
    const dm_worker *me = arg;
    dm_pool *p = me->pool;
    uint32_t seen = 0;
    for (;;) {
        if (!spin(p, no_new_job, seen)) {
            pthread_mutex_lock(&p->lock);
            atomic_fetch_add(&p->sleepers, 1);
            while (job_of(atomic_load(&p->claim)) == seen)
                pthread_cond_wait(&p->wake, &p->lock);
            atomic_fetch_sub(&p->sleepers, 1);
            pthread_mutex_unlock(&p->lock);
        }
        if (atomic_load(&p->stop))
            return NULL;
        seen = job_of(atomic_load_explicit(&p->claim, memory_order_acquire));
        if (work(p, seen, me->self) && atomic_load(&p->caller_asleep)) {
            pthread_mutex_lock(&p->lock);
            pthread_cond_signal(&p->done);
            pthread_mutex_unlock(&p->lock);
        }
    }
}

/* Publishes a new claim word (a job, or the stop) and wakes the sleepers. */
static void publish(dm_pool *p, uint64_t claim)
{
    atomic_store(&p->claim, claim);
    if (atomic_load(&p->sleepers)) {
        pthread_mutex_lock(&p->lock);
        pthread_cond_broadcast(&p->wake);
        pthread_mutex_unlock(&p->lock);
    }
}

static void pool_free(dm_pool *p)
{
    if (!p)
        return;
    atomic_store(&p->stop, true);
    publish(p, (uint64_t)(p->job + 1) << 32);
    for (int k = 0; k < p->workers; k++)
        pthread_join(p->tid[k], NULL);
    pthread_cond_destroy(&p->done);
    pthread_cond_destroy(&p->wake);
    pthread_mutex_destroy(&p->lock);
    free(p->tid);
    free(p->who);
    free(p);
}

/* A pool of `workers` threads, or NULL if none could be started. Workers
 * block every signal, so that the host's signals go to its own threads. */
static dm_pool *pool_new(int workers, uint64_t step)
{
    dm_pool *p = calloc(1, sizeof *p);
    if (!p)
        return NULL;
    p->adapt = (dm_adapt){.step = step, .left = HOLD_MIN, .hold = HOLD_MIN};
    p->tid = malloc((size_t)workers * sizeof *p->tid);
    p->who = malloc((size_t)workers * sizeof *p->who);
    if (!p->tid || !p->who || pthread_mutex_init(&p->lock, NULL)) {
        free(p->tid);
        free(p->who);
        free(p);
        return NULL;
    }
    pthread_cond_init(&p->wake, NULL);
    pthread_cond_init(&p->done, NULL);
    sigset_t all, old;
    sigfillset(&all);
    pthread_sigmask(SIG_SETMASK, &all, &old);
    for (; p->workers < workers; p->workers++) {
        p->who[p->workers] = (dm_worker){p, p->workers + 1};
        if (pthread_create(&p->tid[p->workers], NULL, worker, &p->who[p->workers]))
            break;
    }
    pthread_sigmask(SIG_SETMASK, &old, NULL);
    if (!p->workers) {
        pool_free(p);
        return NULL;
    }
    return p;
}

void dm_threads_free(demill_world *w)
{
    dm_base *b = dm_base_of(w);
    pool_free(b->pool);
    b->pool = NULL;
}

/* The processors this process may run on. */
static int processors(void)
{
#ifdef CPU_COUNT
    cpu_set_t set;
    if (!sched_getaffinity(0, sizeof set, &set))
        return CPU_COUNT(&set);
#endif
    const long n = sysconf(_SC_NPROCESSORS_ONLN);
    return n > 0 ? (int)n : 1;
}

int dm_threads_available(int requested)
{
    if (requested)
        return requested;
    const char *env = getenv("OMP_NUM_THREADS");
    const long n = env ? strtol(env, NULL, 10) : 0;
    return n > 0 ? (int)(n < DM_MAX_THREADS ? n : DM_MAX_THREADS) : processors();
}

/* Runs job `job` (published) with the workers: the caller's share, then its
 * wait for the ranges still running, spinning and then asleep. */
static void run_job(dm_pool *p, uint32_t job)
{
    work(p, job, 0);
    if (spin(p, ranges_left, 0))
        return;
    pthread_mutex_lock(&p->lock);
    atomic_store(&p->caller_asleep, 1);
    while (atomic_load(&p->left))
        pthread_cond_wait(&p->done, &p->lock);
    atomic_store(&p->caller_asleep, 0);
    pthread_mutex_unlock(&p->lock);
}
#else
int dm_threads_available(int requested)
{
    return requested > 1 ? 0 : 1;
}

void dm_threads_free(demill_world *w)
{
    (void)w;
}
#endif

/* The number of ranges dm_parallel() splits [0, n) into: 1 on one thread,
 * for fewer than 2 × MIN_PER_RANGE particles, and in the steps that the
 * world's pool runs on one thread (dm_adapt); else one per thread, at
 * least MIN_PER_RANGE particles each. */
int dm_ranges(const demill_world *w, uint32_t n)
{
    const dm_base *b = dm_base_of_const(w);
    const uint32_t most = n / MIN_PER_RANGE;
    const uint32_t want = (uint32_t)b->threads;
    if (b->threads <= 1 || most <= 1)
        return 1;
#ifdef DEMILL_HAVE_THREADS
    dm_pool *p = b->pool;
    if (p) {
        if (p->adapt.step != b->steps) {
            next_step(&p->adapt, b->steps);
            balance_step(&p->balance);
        }
        if (p->adapt.solo)
            return 1;
    }
#endif
    const uint32_t ranges = want < most ? want : most;
    return (int)(ranges < DM_MAX_THREADS ? ranges : DM_MAX_THREADS);
}

/* Calls fn(w, arg, t, begin, end) for ranges t = 0 .. ranges - 1 that split
 * [0, n) (into equal parts, or where dm_balance moved the cuts), on the
 * world's threads; returns the number of ranges (at most DM_MAX_THREADS).
 * Loops with results per range write them to arg at index t, to be
 * combined in range order. If no worker can be started, the calling thread
 * runs every range: slower, the same results. */
int dm_parallel(demill_world *w, uint32_t n, dm_range_fn fn, void *arg)
{
    const int ranges = dm_ranges(w, n);
#ifdef DEMILL_HAVE_THREADS
    dm_base *b = dm_base_of(w);
    if (ranges > 1 && !b->pool)
        b->pool = pool_new(b->threads - 1, b->steps);
    dm_pool *p = b->pool;
    if (p) {
        const double start = ns_now();
        if (ranges > 1) {
            p->w = w;
            p->fn = fn;
            p->arg = arg;
            p->n = n;
            atomic_store_explicit(&p->left, ranges, memory_order_relaxed);
            const uint32_t job = ++p->job;
            for (int r = 0; r < ranges; r++)
                atomic_store_explicit(&p->taken[r], job - 1, memory_order_relaxed);
            publish(p, (uint64_t)job << 32 | (uint64_t)ranges);
            run_job(p, job);
            balance_note(&p->balance, n, ranges);
        } else {
            fn(w, arg, 0, 0, n);
        }
        p->adapt.spent += ns_now() - start;
        return ranges;
    }
#endif
    for (int t = 0; t < ranges; t++)
        fn(w, arg, t, equal_cut(n, t, ranges), equal_cut(n, t + 1, ranges));
    return ranges;
}
