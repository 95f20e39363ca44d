/* SPDX-License-Identifier: BSD-3-Clause */
/* The "fmu" output (docs/export.md): an FMI 2.0 Model Exchange FMU. The C
 * export and the fmi2 glue are written to a private temporary folder
 * (mkdtemp), compiled there into a shared library by $CC (or cc), and zipped
 * with modelDescription.xml and the sources into the output buffer; the
 * folder is removed. The compiler runs in that folder on relative names so
 * no path of this machine enters the library. The command line and
 * libbgdraw both build it here; the compiler's own messages go to the
 * process's standard error, ours into the output's diagnostics.
 *
 * With bg_output_opts.catch_signals (the command line; a library must not
 * take a program's signals) an interrupted build leaves nothing behind:
 * while the folder exists, SIGINT, SIGTERM, SIGHUP and SIGQUIT only set a
 * flag (and pass SIGTERM to the compiler, which runs in its own process
 * group with TMPDIR in the folder, so its own temporary files are ours to
 * remove); the build stops at the next step, kills what is left of the
 * compiler's group, removes the folder and then dies of the same signal.
 * SIGPIPE is ignored meanwhile (a closed stderr while the compiler's errors
 * are relayed is a failed write, not a death), and the compiler gets its
 * default disposition back. The two flags below are the process's, like
 * its signal handlers: only a build that catches signals writes them. */
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "base/fileio.h"
#include "base/log.h"
#include "export/export.h"
#include "output/output_int.h"

enum { FMU_FILES = 4 }; /* P.h, P.c, P_fmi2.c, P.so in the temporary folder */

typedef struct fmu_build {
  bg_output *w;     /* where errors go */
  const bg_log *log; /* -v: what is being compiled; nullable */
  int signals;      /* stop signals caught (the command line) */
  char dir[4096];
  char name[FMU_FILES][200]; /* file names inside dir */
  bg_strbuf text[FMU_FILES - 1];
} fmu_build;

/* ------------------------------------------------------------ signals */
static const int stop_signals[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT};
enum { NSTOP = sizeof stop_signals / sizeof *stop_signals };
static volatile sig_atomic_t stop_signal; /* the first stop signal received, 0 none */
static volatile sig_atomic_t compiler_pgid; /* the running compiler's group, 0 none */

static void on_stop(int sig) {
  if (!stop_signal) stop_signal = sig;
  if (compiler_pgid > 0) kill(-(pid_t)compiler_pgid, SIGTERM); /* gcc removes its temporaries */
}

typedef struct saved_signals { struct sigaction stop[NSTOP], pipe; } saved_signals;

static void catch_signals(saved_signals *sv) {
  struct sigaction sa;
  memset(&sa, 0, sizeof sa);
  sa.sa_handler = on_stop;
  sigemptyset(&sa.sa_mask);
  stop_signal = 0, compiler_pgid = 0;
  for (int i = 0; i < NSTOP; i++) sigaction(stop_signals[i], &sa, &sv->stop[i]);
  sa.sa_handler = SIG_IGN;
  sigaction(SIGPIPE, &sa, &sv->pipe);
}

static void restore_signals(const saved_signals *sv) {
  for (int i = 0; i < NSTOP; i++) sigaction(stop_signals[i], &sv->stop[i], NULL);
  sigaction(SIGPIPE, &sv->pipe, NULL);
}

/* After the folder is gone: die of the stop signal as if it had not been caught. */
static void die_of_stop_signal(const saved_signals *sv) {
  int sig = stop_signal;
  restore_signals(sv);
  if (!sig) return;
  signal(sig, SIG_DFL);
  raise(sig);
  _exit(128 + sig); /* the signal was blocked: exit with the shell's status for it */
}

/* ------------------------------------------------------------ files */
static int write_in(const fmu_build *b, int k, const void *data, size_t len) {
  char path[4400];
  snprintf(path, sizeof path, "%s/%s", b->dir, b->name[k]);
  if (bg_write_file_atomic(path, data, len) == 0) return 0;
  bg_out_error(b->w, BG_OUT_WRITE, "cannot write '%s': %s", path, bg_file_strerror(errno));
  return -1;
}

/* ------------------------------------------------------------ the compiler */
static int stopped(const fmu_build *b) { return b->signals && stop_signal; }

static void set_group(const fmu_build *b, pid_t pgid) {
  if (b->signals) compiler_pgid = pgid; /* only for on_stop, only when it is installed */
}

/* Ends the compiler's process group: SIGTERM, up to 2 s for it to go, then
 * SIGKILL; reaps the compiler. */
static void end_compiler(const fmu_build *b, pid_t pid) {
  kill(-pid, SIGTERM);
  for (int i = 0; i < 200; i++) {
    if (waitpid(pid, NULL, WNOHANG) == pid) break;
    nanosleep(&(struct timespec){0, 10000000}, NULL);
  }
  kill(-pid, SIGKILL); /* what is left of the group (cc1, as, ld) */
  while (waitpid(pid, NULL, 0) < 0 && errno == EINTR) {}
  set_group(b, 0);
}

static void log_command(const fmu_build *b, char *const argv[]) {
  if (!bg_log_on(b->log, BG_LOG_PROGRESS)) return;
  char line[2048];
  size_t len = 0;
  for (int i = 0; argv[i] && len < sizeof line - 1; i++)
    len += (size_t)snprintf(line + len, sizeof line - len, "%s%s", i ? " " : "", argv[i]);
  bg_logf(b->log, BG_LOG_PROGRESS, "compiling the FMU's library (%zu bytes of C) in %s: %s",
          b->text[1].len + b->text[2].len + b->text[0].len, b->dir, line);
}

/* The child: its own group, default signals, our folder; on a failed exec
 * its errno goes up the close-on-exec pipe (so the message is the parent's,
 * in the output's diagnostics). */
static void run_child(const fmu_build *b, char *const argv[], int report_fd) {
  setpgid(0, 0);
  if (b->signals) {
    for (int i = 0; i < NSTOP; i++) signal(stop_signals[i], SIG_DFL);
    signal(SIGPIPE, SIG_DFL);
  }
  setenv("TMPDIR", b->dir, 1); /* the compiler's temporaries in our folder */
  if (chdir(b->dir) == 0) execvp(argv[0], argv);
  int e = errno;
  if (write(report_fd, &e, sizeof e) < 0) {} /* nothing more to do if even this fails */
  _exit(127);
}

/* $CC split at blanks ("ccache gcc" works), then the flags and files. */
static int compile(const fmu_build *b) {
  const char *cc = getenv("CC");
  if (!cc || !*cc) cc = "cc";
  char ccbuf[1024], *argv[64];
  int n = 0;
  snprintf(ccbuf, sizeof ccbuf, "%s", cc);
  char *save = NULL;
  for (char *tok = strtok_r(ccbuf, " \t", &save); tok && n < 40; tok = strtok_r(NULL, " \t", &save))
    argv[n++] = tok;
  const char *tail[] = {"-shared", "-fPIC", "-O2", "-o", b->name[3], b->name[1], b->name[2], "-lm", NULL};
  for (int i = 0; tail[i]; i++) argv[n++] = (char *)tail[i];
  argv[n] = NULL;
  log_command(b, argv);
  fflush(NULL);
  if (stopped(b)) return -1;
  int fds[2];
  if (pipe(fds) < 0)
    return bg_out_error(b->w, BG_OUT_WRITE, "cannot start the C compiler: %s%s", strerror(errno), ""), -1;
  fcntl(fds[0], F_SETFD, FD_CLOEXEC), fcntl(fds[1], F_SETFD, FD_CLOEXEC); /* cannot fail on new fds */
  pid_t pid = fork();
  if (pid < 0) {
    close(fds[0]), close(fds[1]);
    return bg_out_error(b->w, BG_OUT_WRITE, "cannot start the C compiler: %s%s", strerror(errno), ""), -1;
  }
  if (pid == 0) run_child(b, argv, fds[1]);
  close(fds[1]);
  setpgid(pid, pid); /* both sides: no race with the first signal */
  set_group(b, pid);
  if (stopped(b)) kill(-pid, SIGTERM); /* arrived between fork and here */
  int exec_errno = 0;
  ssize_t got;
  while ((got = read(fds[0], &exec_errno, sizeof exec_errno)) < 0 && errno == EINTR && !stopped(b)) {}
  close(fds[0]);
  int st = 0;
  pid_t w;
  while ((w = waitpid(pid, &st, 0)) < 0 && errno == EINTR && !stopped(b)) {}
  if (stopped(b) || w < 0) {
    if (w != pid) end_compiler(b, pid);
    else kill(-pid, SIGKILL); /* the compiler is gone; its helpers too */
    set_group(b, 0);
    return -1;
  }
  kill(-pid, SIGKILL); /* a helper the compiler left running, if any */
  set_group(b, 0);
  if (got == (ssize_t)sizeof exec_errno) {
    bg_out_error(b->w, BG_OUT_WRITE, "cannot run the C compiler '%s' (set CC to one): %s", argv[0],
                 strerror(exec_errno));
    return -1;
  }
  if (WIFEXITED(st) && WEXITSTATUS(st) == 0) return 0;
  bg_out_error(b->w, BG_OUT_WRITE, "the C compiler '%s' failed to build the FMU's shared library%s",
               argv[0], "");
  return -1;
}

/* The archive: modelDescription.xml, sources/, binaries/linux64/P.so. */
static void archive(const fmu_build *b, const char *P, const bg_strbuf *xml, const char *so, size_t solen,
                    bg_strbuf *zip) {
  char names[FMU_FILES][300];
  snprintf(names[0], sizeof names[0], "sources/%s", b->name[0]);
  snprintf(names[1], sizeof names[1], "sources/%s", b->name[1]);
  snprintf(names[2], sizeof names[2], "sources/%s", b->name[2]);
  snprintf(names[3], sizeof names[3], "binaries/linux64/%s.so", P);
  bg_zip_entry e[FMU_FILES + 1] = {{"modelDescription.xml", bg_sb_str(xml), xml->len}};
  for (int k = 0; k < FMU_FILES - 1; k++) e[k + 1] = (bg_zip_entry){names[k], bg_sb_str(&b->text[k]), b->text[k].len};
  e[FMU_FILES] = (bg_zip_entry){names[3], so, solen};
  bg_export_zip(e, FMU_FILES + 1, zip);
}

/* The folder and everything in it: our files and whatever an interrupted
 * compiler left there (its temporaries go to TMPDIR, our folder). */
static void cleanup(fmu_build *b) {
  char path[4400];
  for (int k = 0; k < FMU_FILES; k++) {
    snprintf(path, sizeof path, "%s/%s", b->dir, b->name[k]);
    unlink(path);
  }
  DIR *d = opendir(b->dir);
  for (struct dirent *e; d && (e = readdir(d));) {
    if (!strcmp(e->d_name, ".") || !strcmp(e->d_name, "..")) continue;
    snprintf(path, sizeof path, "%s/%s", b->dir, e->d_name);
    unlink(path);
  }
  if (d) closedir(d);
  rmdir(b->dir);
  for (int k = 0; k < FMU_FILES - 1; k++) bg_sb_free(&b->text[k]);
}

/* Sources, library, archive into zip; BG_OUT_OK, or BG_OUT_WRITE after a message. */
static bg_output_status build(fmu_build *b, const bg_eqsys *s, const char *P, bg_strbuf *zip) {
  char guid[64];
  bg_export_c(s, P, b->name[0], &b->text[0], &b->text[1]);
  bg_strbuf all = {0}, xml = {0};
  bg_sb_putn(&all, bg_sb_str(&b->text[0]), b->text[0].len);
  bg_sb_putn(&all, bg_sb_str(&b->text[1]), b->text[1].len);
  bg_export_fmu_guid(bg_sb_str(&all), all.len, guid, sizeof guid);
  bg_sb_free(&all);
  bg_export_fmu_glue(s, P, b->name[0], guid, &b->text[2]);
  bg_export_fmu_description(s, P, guid, &xml);
  bg_output_status rc = BG_OUT_WRITE;
  for (int k = 0; k < FMU_FILES - 1; k++)
    if (stopped(b) || write_in(b, k, bg_sb_str(&b->text[k]), b->text[k].len)) goto done;
  if (compile(b) || stopped(b)) goto done;
  char path[4400];
  snprintf(path, sizeof path, "%s/%s", b->dir, b->name[3]);
  size_t solen = 0;
  char *so = bg_read_file(path, &solen);
  if (!so) {
    bg_out_error(b->w, BG_OUT_WRITE, "cannot read the compiled '%s': %s", path, bg_file_strerror(errno));
    goto done;
  }
  archive(b, P, &xml, so, solen, zip);
  free(so);
  rc = BG_OUT_OK;
done:
  bg_sb_free(&xml);
  return rc;
}

bg_output_status bg_out_fmu(bg_output *w, const bg_output_kind *k, const char *form, const char *path,
                            bg_strbuf *out) {
  (void)k, (void)form;
  char prefix[80];
  bg_eqsys *s = NULL;
  bg_output_status st = bg_out_export_system(w, "fmu", path, &s, prefix, sizeof prefix);
  if (st != BG_OUT_OK) return st;
  if (!bg_eqsys_is_ode(s)) {
    bg_eqsys_free(s);
    char what[4200];
    snprintf(what, sizeof what, "export refused: '%s': ", path ? path : "stdout");
    return bg_out_refuse(w, what, "the model is a DAE (it has algebraic unknowns); FMI 2.0 Model "
                         "Exchange takes ODE models only (docs/export.md)");
  }
  fmu_build b = {.w = w, .log = w->o.render.log, .signals = w->o.catch_signals};
  const char *tmp = getenv("TMPDIR");
  snprintf(b.dir, sizeof b.dir, "%s/bgdraw-fmu-XXXXXX", tmp && *tmp ? tmp : "/tmp");
  saved_signals sv;
  if (b.signals) catch_signals(&sv); /* before the folder exists: no moment without a handler */
  if (!mkdtemp(b.dir)) {
    bg_out_error(w, BG_OUT_WRITE, "cannot make a temporary folder '%s': %s", b.dir, bg_file_strerror(errno));
    if (b.signals) restore_signals(&sv);
    bg_eqsys_free(s);
    return BG_OUT_WRITE;
  }
  snprintf(b.name[0], sizeof b.name[0], "%s.h", prefix);
  snprintf(b.name[1], sizeof b.name[1], "%s.c", prefix);
  snprintf(b.name[2], sizeof b.name[2], "%s_fmi2.c", prefix);
  snprintf(b.name[3], sizeof b.name[3], "%s.so", prefix);
  st = build(&b, s, prefix, out);
  cleanup(&b);
  bg_eqsys_free(s);
  if (b.signals) die_of_stop_signal(&sv); /* returns (handlers restored) unless a stop signal came */
  return st;
}
