/*
 * pcl_flowseg - fast file output: numbers formatted with std::to_chars (or raw little-endian
 * bytes) into a large buffer written to the stream in blocks; a stream's operator<< per number
 * costs several times more.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#pragma once

#include <cstdint>
#include <ostream>
#include <string>
#include <string_view>

namespace pcl_flowseg {

/** \brief Appends text, numbers and raw values, and writes them to \a out in blocks (and when destroyed).
  * Floating-point numbers are written in their shortest form that reads back to the same value. */
class OutputBuffer
{
public:
  explicit OutputBuffer (std::ostream& out);
  ~OutputBuffer ();
  OutputBuffer (const OutputBuffer&) = delete;
  OutputBuffer& operator= (const OutputBuffer&) = delete;

  OutputBuffer& text (std::string_view text);
  OutputBuffer& number (double value);
  OutputBuffer& number (float value);
  OutputBuffer& integer (std::int64_t value);
  OutputBuffer& character (char c);
  /** The bytes of \a value as they lie in memory (little-endian on the machines we build for). */
  template <typename Value>
  OutputBuffer&
  binary (Value value)
  {
    return text (std::string_view (reinterpret_cast<const char*> (&value), sizeof (Value)));
  }
  /** Writes what is buffered to the stream. */
  void flush ();

private:
  void flushWhenFull ();

  std::ostream& out_;
  std::string buffer_;
};

} // namespace pcl_flowseg
