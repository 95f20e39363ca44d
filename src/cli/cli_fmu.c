/* SPDX-License-Identifier: BSD-3-Clause */
/* -o NAME.fmu (docs/export.md): an FMI 2.0 Model Exchange FMU. The C export
 * and the fmi2 glue are written to a private temporary folder (mkdtemp),
 * compiled there into a shared library by $CC (or cc), and zipped with
 * modelDescription.xml and the sources; the archive is written atomically and
 * the folder removed. The compiler runs in that folder on relative names so
 * no path of this machine enters the library.
 *
 * Interrupted builds leave nothing behind: while the folder exists, SIGINT,
 * SIGTERM, SIGHUP and SIGQUIT only set a flag (and pass SIGTERM to the
 * compiler, which runs in its own process group with TMPDIR in the folder,
 * so its own temporary files are ours to remove); the build stops at the
 * next step, kills what is left of the compiler's group, removes the folder
 * and then dies of the same signal. SIGPIPE is ignored meanwhile (a closed
 * stderr while the compiler's errors are relayed is a failed write, not a
 * death), and the compiler gets its default disposition back. */
#include <dirent.h>
#include <errno.h>
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
#include "cli/cli_run.h"
#include "export/export.h"

enum { FMU_FILES = 4 }; /* P.h, P.c, P_fmi2.c, P.so in the temporary folder */

typedef struct fmu_build {
  char dir[4096];
  char name[FMU_FILES][200]; /* file names inside dir */
  bg_strbuf text[FMU_FILES - 1];
} fmu_build;

static const bg_log *fmu_log; /* -v: what is being compiled */
void cli_fmu_set_log(const bg_log *log) { fmu_log = log; }

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
  fprintf(stderr, "bgdraw: error: cannot write '%s': %s\n", path, bg_file_strerror(errno));
  return -1;
}

/* ------------------------------------------------------------ the compiler */
/* Ends the compiler's process group: SIGTERM, up to 2 s for it to go, then
 * SIGKILL; reaps the compiler. */
static void end_compiler(pid_t pid) {
  kill(-pid, SIGTERM);
  for (int i = 0; i < 200; i++) {
    if (waitpid(pid, NULL, WNOHANG) == pid) break;
    nanosleep(&(struct timespec){0, 10000000}, NULL);
  }
  kill(-pid, SIGKILL); /* what is left of the group (cc1, as, ld) */
  while (waitpid(pid, NULL, 0) < 0 && errno == EINTR) {}
  compiler_pgid = 0;
}

/* $CC split at blanks ("ccache gcc" works), then the flags and files. */
static int compile(const fmu_build *b) {
  const char *cc = getenv("CC");
  if (!cc || !*cc) cc = "cc";
  char ccbuf[1024], *argv[64];
  int n = 0;
  snprintf(ccbuf, sizeof ccbuf, "%s", cc);
  for (char *tok = strtok(ccbuf, " \t"); tok && n < 40; tok = strtok(NULL, " \t")) argv[n++] = tok;
  const char *tail[] = {"-shared", "-fPIC", "-O2", "-o", b->name[3], b->name[1], b->name[2], "-lm", NULL};
  for (int i = 0; tail[i]; i++) argv[n++] = (char *)tail[i];
  argv[n] = NULL;
  if (bg_log_on(fmu_log, BG_LOG_PROGRESS)) {
    char line[2048];
    size_t len = 0;
    for (int i = 0; argv[i] && len < sizeof line - 1; i++)
      len += (size_t)snprintf(line + len, sizeof line - len, "%s%s", i ? " " : "", argv[i]);
    bg_logf(fmu_log, BG_LOG_PROGRESS, "compiling the FMU's library (%zu bytes of C) in %s: %s",
            b->text[1].len + b->text[2].len + b->text[0].len, b->dir, line);
  }
  fflush(NULL);
  if (stop_signal) return -1;
  pid_t pid = fork();
  if (pid < 0) return fprintf(stderr, "bgdraw: error: cannot start the C compiler: %s\n", strerror(errno)), -1;
  if (pid == 0) {
    setpgid(0, 0);
    for (int i = 0; i < NSTOP; i++) signal(stop_signals[i], SIG_DFL);
    signal(SIGPIPE, SIG_DFL);
    setenv("TMPDIR", b->dir, 1); /* the compiler's temporaries in our folder */
    if (chdir(b->dir) == 0) execvp(argv[0], argv);
    fprintf(stderr, "bgdraw: error: cannot run the C compiler '%s' (set CC to one): %s\n", argv[0], strerror(errno));
    _exit(127);
  }
  setpgid(pid, pid); /* both sides: no race with the first signal */
  compiler_pgid = pid;
  if (stop_signal) kill(-pid, SIGTERM); /* arrived between fork and here */
  int st = 0;
  pid_t w;
  while ((w = waitpid(pid, &st, 0)) < 0 && errno == EINTR && !stop_signal) {}
  if (stop_signal || w < 0) {
    if (w != pid) end_compiler(pid);
    else kill(-pid, SIGKILL); /* the compiler is gone; its helpers too */
    compiler_pgid = 0;
    return -1;
  }
  kill(-pid, SIGKILL); /* a helper the compiler left running, if any */
  compiler_pgid = 0;
  if (WIFEXITED(st) && WEXITSTATUS(st) == 0) return 0;
  if (!(WIFEXITED(st) && WEXITSTATUS(st) == 127))
    fprintf(stderr, "bgdraw: error: the C compiler '%s' failed to build the FMU's shared library\n", argv[0]);
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

/* Sources, library, archive into zip; EXIT_OK or EXIT_WRITE after a message. */
static int build(fmu_build *b, const bg_eqsys *s, const char *P, bg_strbuf *zip) {
  char guid[64];
  bg_export_c(s, P, b->name[0], &b->text[0], &b->text[1]);
  bg_strbuf all = {0}, xml = {0};
  bg_sb_putn(&all, bg_sb_str(&b->text[0]), b->text[0].len);
  bg_sb_putn(&all, bg_sb_str(&b->text[1]), b->text[1].len);
  bg_export_fmu_guid(bg_sb_str(&all), all.len, guid, sizeof guid);
  bg_sb_free(&all);
  bg_export_fmu_glue(s, P, b->name[0], guid, &b->text[2]);
  bg_export_fmu_description(s, P, guid, &xml);
  int rc = EXIT_WRITE;
  for (int k = 0; k < FMU_FILES - 1; k++)
    if (stop_signal || write_in(b, k, bg_sb_str(&b->text[k]), b->text[k].len)) goto done;
  if (compile(b) || stop_signal) goto done;
  char path[4400];
  snprintf(path, sizeof path, "%s/%s", b->dir, b->name[3]);
  size_t solen = 0;
  char *so = bg_read_file(path, &solen);
  if (!so) {
    fprintf(stderr, "bgdraw: error: cannot read the compiled '%s': %s\n", path, bg_file_strerror(errno));
    goto done;
  }
  archive(b, P, &xml, so, solen, zip);
  free(so);
  rc = EXIT_OK;
done:
  bg_sb_free(&xml);
  return rc;
}

int cli_write_fmu(const bg_eqsys *s, const char *prefix, const char *path) {
  if (!bg_eqsys_is_ode(s)) {
    fprintf(stderr, "bgdraw: export refused: '%s': the model is a DAE (it has algebraic "
            "unknowns); FMI 2.0 Model Exchange takes ODE models only (docs/export.md)\n", path);
    return EXIT_SIM; /* a refusal, as the docs give refusals: status 3 */
  }
  fmu_build b = {0};
  const char *tmp = getenv("TMPDIR");
  snprintf(b.dir, sizeof b.dir, "%s/bgdraw-fmu-XXXXXX", tmp && *tmp ? tmp : "/tmp");
  saved_signals sv;
  catch_signals(&sv); /* before the folder exists: no moment without a handler */
  if (!mkdtemp(b.dir)) {
    fprintf(stderr, "bgdraw: error: cannot make a temporary folder '%s': %s\n", b.dir, bg_file_strerror(errno));
    restore_signals(&sv);
    return EXIT_WRITE;
  }
  snprintf(b.name[0], sizeof b.name[0], "%s.h", prefix);
  snprintf(b.name[1], sizeof b.name[1], "%s.c", prefix);
  snprintf(b.name[2], sizeof b.name[2], "%s_fmi2.c", prefix);
  snprintf(b.name[3], sizeof b.name[3], "%s.so", prefix);
  bg_strbuf zip = {0};
  int rc = build(&b, s, prefix, &zip);
  cleanup(&b);
  die_of_stop_signal(&sv); /* returns (handlers restored) unless a stop signal came */
  if (rc == EXIT_OK) rc = cli_write_text(path, &zip);
  bg_sb_free(&zip);
  return rc;
}
