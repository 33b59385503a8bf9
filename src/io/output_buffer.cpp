/*
 * pcl_flowseg - fast file output.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "io/output_buffer.h"

#include <charconv>

namespace pcl_flowseg {

namespace {
constexpr std::size_t kBlockBytes = 1 << 20;

template <typename Number>
void
appendNumber (std::string& buffer, Number value)
{
  char digits[64];
  const std::to_chars_result r = std::to_chars (digits, digits + sizeof (digits), value);
  buffer.append (digits, static_cast<std::size_t> (r.ptr - digits));
}
} // namespace

OutputBuffer::OutputBuffer (std::ostream& out) : out_ (out) { buffer_.reserve (kBlockBytes + 256); }

OutputBuffer::~OutputBuffer () { flush (); }

void
OutputBuffer::flush ()
{
  out_.write (buffer_.data (), static_cast<std::streamsize> (buffer_.size ()));
  buffer_.clear ();
}

void
OutputBuffer::flushWhenFull ()
{
  if (buffer_.size () >= kBlockBytes)
    flush ();
}

OutputBuffer&
OutputBuffer::text (std::string_view text)
{
  buffer_.append (text);
  flushWhenFull ();
  return *this;
}

OutputBuffer&
OutputBuffer::number (double value)
{
  appendNumber (buffer_, value);
  flushWhenFull ();
  return *this;
}

OutputBuffer&
OutputBuffer::number (float value)
{
  appendNumber (buffer_, value);
  flushWhenFull ();
  return *this;
}

OutputBuffer&
OutputBuffer::integer (std::int64_t value)
{
  appendNumber (buffer_, value);
  flushWhenFull ();
  return *this;
}

OutputBuffer&
OutputBuffer::character (char c)
{
  buffer_.push_back (c);
  flushWhenFull ();
  return *this;
}

} // namespace pcl_flowseg
