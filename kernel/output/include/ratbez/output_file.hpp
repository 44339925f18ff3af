#pragma once
// Output files written safely, the same way for every format (issue 14, items 1-6):
// - the data goes to a NEW temporary file in the target's folder, created exclusively (O_CREAT | O_EXCL |
//   O_NOFOLLOW: a planted name or symbolic link is never opened, let alone followed), with a short random
//   name (a target name of up to NAME_MAX bytes works: nothing is appended to it);
// - it is flushed to disk (fsync) and renamed over the target, which is atomic: a reader, a crash or a kill
//   at any moment sees the old file or the whole new one, never a truncated or spliced file; of concurrent
//   writers to one path each produces a whole file and the last rename wins;
// - on any error the temporary file is removed and the target left as it was; remove_temporaries_on_signals()
//   (the command installs it) removes it on every signal that ends the program too, and says so in one line;
// - an existing target keeps its permission bits; one the user may not write (a read-only file, as a shell
//   redirect or OpenSCAD would refuse it) is refused, and so is a symbolic link at the target (one rule for
//   every format: the link is neither followed nor replaced; name the file it points to instead), a folder
//   or any other file that is not a regular file.
// Errors are ratbez::Error naming "path" with a reason that names the file, or the folder when the folder
// is at fault (missing, not writable).

#include <functional>
#include <ostream>
#include <string>

namespace ratbez::output {

// Writes the file `path` with what `write` puts on the stream.
void write_file(const std::string& path, const std::function<void(std::ostream& out)>& write);

// The same for a writer that opens a file by name itself (OpenCASCADE's STEP and BREP writers): `write` gets
// a name that opens the temporary file (its /proc/self/fd link, bound to the very file created, whatever
// happens to its name meanwhile) and must write the whole file there.
void write_file_by_name(const std::string& path, const std::function<void(const std::string& name)>& write);

// Every signal that ends the program from outside (SIGHUP, SIGINT, SIGQUIT, SIGPIPE, SIGALRM, SIGTERM, SIGUSR1,
// SIGUSR2, SIGXCPU, SIGXFSZ, SIGVTALRM, SIGPROF, SIGPOLL, SIGPWR, SIGSTKFLT; not those ignored at start) removes
// the temporary files being written and writes one line on stderr, "<program>: stopped by SIGHUP (the terminal
// hung up); 'out.step' not written (its temporary file was removed)", then takes its default action (the
// process ends as it would have). SIGXFSZ, a write past the file size limit, is a write error instead:
// "error: path: 'out.stl' reached the file size limit (ulimit -f) and was not written", exit code 2.
// For programs (the command), not for libraries hosted by another (Python, FreeCAD).
void remove_temporaries_on_signals(const char* program = "ratbez");

}  // namespace ratbez::output
