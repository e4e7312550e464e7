#pragma once
// The exit codes of mesochain (the table in docs/command-line.md). Every subcommand returns one
// of these; main maps CLI11's parse errors to kUsageError.
namespace mesochain::app {

inline constexpr int kSuccess = 0;
// A failure that is not the input's fault (a numerical failure, a file system error mid-run).
inline constexpr int kFailure = 1;
// Bad command line or bad input: unknown option, value out of range, missing or invalid input
// file, an unwritable output path (mesochain::InputError); nothing was computed.
inline constexpr int kUsageError = 2;
// Finished, but a relaxation (run, or a scan point) did not converge within its step limit.
inline constexpr int kNotConverged = 3;
// Stopped as asked (scan --stop-after) before the end; continue with --resume.
inline constexpr int kStoppedAsAsked = 4;

}  // namespace mesochain::app
