#include "CsvWriter.h"

#include <charconv>

namespace riemann
{
namespace cli
{
namespace
{
/// Written to the stream once this much is buffered.
constexpr std::size_t BlockSize = 1 << 16;
}

CsvWriter::CsvWriter(std::ostream& out)
  : Out(out)
{
  this->Buffer.reserve(BlockSize + 256);
}

CsvWriter::~CsvWriter()
{
  this->Out.write(this->Buffer.data(), static_cast<std::streamsize>(this->Buffer.size()));
}

void CsvWriter::Separate()
{
  if (this->RowStarted)
  {
    this->Buffer += ',';
  }
  this->RowStarted = true;
}

CsvWriter& CsvWriter::Add(double value)
{
  this->Separate();
  char text[32];
  // Shortest round-trip form ("0.1", "1e-05", "nan", "inf").
  const std::to_chars_result written = std::to_chars(text, text + sizeof(text), value);
  this->Buffer.append(text, written.ptr);
  return *this;
}

CsvWriter& CsvWriter::Add(long long value)
{
  this->Separate();
  char text[24];
  const std::to_chars_result written = std::to_chars(text, text + sizeof(text), value);
  this->Buffer.append(text, written.ptr);
  return *this;
}

CsvWriter& CsvWriter::AddText(const std::string& text)
{
  this->Separate();
  this->Buffer += text;
  return *this;
}

void CsvWriter::EndRow()
{
  this->Buffer += '\n';
  this->RowStarted = false;
  this->FlushIfFull();
}

void CsvWriter::FlushIfFull()
{
  if (this->Buffer.size() >= BlockSize)
  {
    this->Out.write(this->Buffer.data(), static_cast<std::streamsize>(this->Buffer.size()));
    this->Buffer.clear();
  }
}

bool CsvWriter::Finish()
{
  this->Out.write(this->Buffer.data(), static_cast<std::streamsize>(this->Buffer.size()));
  this->Buffer.clear();
  this->Out.flush();
  return static_cast<bool>(this->Out);
}
}
}
