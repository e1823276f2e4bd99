// Csv.h - the one small CSV writer (and reader) every Hitbox file of rows goes through:
// replays (Replay.h) and the contact timeline (Timeline.h). RFC 4180: fields separated by
// commas, rows ended by "\r\n"; a field holding a comma, a quote, a CR or an LF is wrapped in
// quotes, with each quote doubled. Nothing else is changed: an empty field is written empty.
#pragma once

#include <istream>
#include <ostream>
#include <string>
#include <vector>

namespace hitbox
{

// Writes rows of text fields to a stream it does not own.
class CsvWriter
{
public:
    explicit CsvWriter(std::ostream& out) : out(out) {}

    // Writes one row; an empty `fields` writes an empty line.
    void row(const std::vector<std::string>& fields);

private:
    std::ostream& out;
};

// `value` written so that reading it back gives the same float bit for bit (9 significant
// digits, '.' as the point whatever the locale); NaN as "nan", infinities as "inf"/"-inf".
[[nodiscard]] std::string exactText(float value);
// Reads what exactText wrote; false (and `value` unchanged) for anything else.
[[nodiscard]] bool readExact(const std::string& text, float& value);

// Reads the next row into `fields`; false at the end of the stream. A quoted field may hold
// commas and line breaks; "\r\n" and "\n" both end a row. `problem` is set (and false
// returned) for a quote left open at the end of the stream.
[[nodiscard]] bool readCsvRow(std::istream& in, std::vector<std::string>& fields,
                              std::string& problem);

} // namespace hitbox
