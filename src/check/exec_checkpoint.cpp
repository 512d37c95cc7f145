// raycam-exec FD PROGRAM [ARGS...]: the last step of a sandbox's set-up (sandbox_policy.h). bwrap runs it
// once every namespace, mount and filter is in place; it writes 'S' on FD, makes FD close on exec, and
// execs PROGRAM. If the exec fails it writes the errno after the 'S' and exits 127. So the checker reads
// facts, not what a student prints: no byte, the sandbox failed (the checker's error); 'S' alone, the
// program ran (whatever it then did is the student's); 'S' and an errno, the program could not start.
// The student's program never holds FD (closed by its exec), and bwrap's own processes that still hold it
// sit outside the sandbox's PID namespace, out of its reach.
#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>

int main(int argc, char** argv) {
  if (argc < 3) {
    const char usage[] = "usage: raycam-exec FD PROGRAM [ARGS...] (raycam-cli check's sandbox starts it)\n";
    ssize_t ignored = write(2, usage, sizeof usage - 1);
    (void)ignored;
    return 2;
  }
  const int fd = std::atoi(argv[1]);
  if (fcntl(fd, F_SETFD, FD_CLOEXEC) != 0 || write(fd, "S", 1) != 1) return 126;
  execv(argv[2], argv + 2);
  const int code = errno;
  ssize_t ignored = write(fd, &code, sizeof code);
  (void)ignored;
  return 127;
}
