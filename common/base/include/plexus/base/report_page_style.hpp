// The look the HTML reports share (`plexus report`, `plexus bench`): the page, its headings,
// code, the list of sections and the figures. Each report adds the styles of its own tables.
#pragma once

namespace plexus {

inline constexpr const char* kReportPageStyle = R"(
body { font-family: sans-serif; margin: 0 auto; max-width: 1280px; padding: 0 1.5em 3em; color: #1a1a1a; }
h1 { margin-top: 1em; }
h2 { border-bottom: 1px solid #ccc; padding-bottom: .2em; margin-top: 2em; }
code { font-size: 95%; }
nav ul { columns: 3; }
figure { margin: 1.5em 0; }
figure img { max-width: 100%; height: auto; border: 1px solid #ddd; }
figcaption { color: #333; margin-top: .3em; }
figcaption b { display: block; }
)";

}  // namespace plexus
