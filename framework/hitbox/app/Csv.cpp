#include "hitbox/app/Csv.h"

#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <locale>
#include <sstream>

namespace hitbox
{

void CsvWriter::row(const std::vector<std::string>& fields)
{
    for (std::size_t i = 0; i < fields.size(); ++i)
    {
        if (i > 0)
            out << ',';
        const std::string& field = fields[i];
        if (field.find_first_of(",\"\r\n") == std::string::npos)
        {
            out << field;
            continue;
        }
        out << '"';
        for (char c : field)
            out << (c == '"' ? "\"\"" : std::string(1, c));
        out << '"';
    }
    out << "\r\n";
}

std::string exactText(float value)
{
    if (std::isnan(value))
        return "nan";
    if (std::isinf(value))
        return value > 0.f ? "inf" : "-inf";
    std::ostringstream text;
    text.imbue(std::locale::classic());
    // 9 significant digits always read back as the same float (std::numeric_limits<float>::
    // max_digits10; IEEE 754-2008, section 5.12.2).
    text << std::setprecision(9) << value;
    return text.str();
}

bool readExact(const std::string& text, float& value)
{
    if (text == "nan" || text == "inf" || text == "-inf")
    {
        value = text == "nan" ? std::nanf("") : (text == "inf" ? HUGE_VALF : -HUGE_VALF);
        return true;
    }
    std::istringstream in(text);
    in.imbue(std::locale::classic());
    float read = 0.f;
    in >> read;
    if (text.empty() || in.fail() || in.peek() != std::char_traits<char>::eof())
        return false;
    value = read;
    return true;
}

bool readCsvRow(std::istream& in, std::vector<std::string>& fields, std::string& problem)
{
    fields.clear();
    if (in.peek() == std::char_traits<char>::eof())
        return false;
    std::string field;
    bool quoted = false;
    char c = 0;
    while (in.get(c))
    {
        if (quoted)
        {
            if (c != '"')
                field += c;
            else if (in.peek() == '"')
                field += static_cast<char>(in.get());
            else
                quoted = false;
        }
        else if (c == '"')
            quoted = true;
        else if (c == ',')
        {
            fields.push_back(field);
            field.clear();
        }
        else if (c == '\n')
            break;
        else if (c == '\r' && in.peek() == '\n')
            continue;
        else
            field += c;
    }
    if (quoted)
    {
        problem = "a quoted field is never closed";
        return false;
    }
    fields.push_back(field);
    return true;
}

} // namespace hitbox
