#pragma once

// Writing a whole file so that readers (and a crash, or a full disk) only
// ever see the previous contents or the complete new ones. Every file mlndt
// and its tools write goes through WriteFileAtomically.
//
// Steps:
//  1. lstat(path). A symbolic link, directory, device node, FIFO or socket
//     at `path` is refused: nothing is written through it and it is not
//     replaced. A regular file keeps its permission bits (mode & 07777); a
//     new file gets 0644 minus the umask.
//  2. A temporary file ".<name>.tmp.XXXXXX" is created in the folder of
//     `path` (so the rename stays on one file system) with O_CREAT | O_EXCL
//     and a random suffix, retried on a name clash, as mkstemp does: two
//     threads or processes writing the same path each get their own
//     temporary file. The leading dot keeps it out of "*.pcd"-style listings.
//     The writer holds an exclusive flock() on its temporary file until the
//     rename. Before creating it, temporary files of the same target that
//     no writer holds (left by a killed writer: the kernel dropped its lock)
//     are removed; a cleaner that removed a file in the instant before its
//     writer locked it makes that writer retry with a new name.
//  3. Every write() and the close() are checked (short writes are resumed,
//     EINTR retried); the file is fsync()ed before it is renamed onto
//     `path`, and the folder is fsync()ed after, so that after a power
//     failure `path` holds the old or the new contents, not an empty file.
//  4. On any failure before the rename (ENOSPC, EFBIG, EIO, EACCES, ...) the
//     temporary file is removed and `path` is left exactly as it was.
//
// Concurrent writers of one path do not corrupt it: each rename is atomic,
// the last one wins, and the file is always one writer's complete output.
// Not defended against: a symbolic link or special file created at `path`
// between the check in step 1 and the rename (rename replaces the link
// itself, it never writes through it), and the owner of a replaced file
// (the new file belongs to the writing user).

#include <string>
#include <string_view>

namespace mlndt {

// Replaces the file at `path` with `bytes` (steps above). Returns false with
// *error = "<path>: <what failed>: <strerror(errno)>" and `path` unchanged.
bool WriteFileAtomically(const std::string& path,
                         std::string_view bytes,
                         std::string* error);

// The checks of WriteFileAtomically that need no writing: `path` is not a
// symbolic link or special file, and its folder exists and is writable. For
// tools that want to fail before a long computation rather than after it.
bool CheckWritableFilePath(const std::string& path, std::string* error);

}  // namespace mlndt
