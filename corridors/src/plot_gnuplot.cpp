// SPDX-License-Identifier: GPL-3.0-or-later
// Corridor plots made by gnuplot from generated data and script files: the corridor as a
// filled band, the test mean (or corridor mid-line) dashed, the model curve solid, ISO/TS
// 18571 and CORA scores with the grade in the title, units on both axes.
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "hbm/corridors/report.hpp"

namespace fs = std::filesystem;

namespace hbm::corridors {
namespace {

void write_xy(const fs::path& p, const Polyline& c) {
  std::ofstream f(p);
  f.precision(9);
  for (std::size_t i = 0; i < c.x.size(); ++i) f << c.x[i] << ' ' << c.y[i] << '\n';
  if (!f) throw std::runtime_error("cannot write " + p.string());
}

std::string gp_escape(const std::string& s) {
  std::string o;
  for (char c : s) {
    if (c == '"' || c == '\\') o += '\\';
    o += c;
  }
  return o;
}

std::string fixed(double v, int d) {
  std::ostringstream s;
  s.setf(std::ios::fixed);
  s.precision(d);
  s << v;
  return s.str();
}

std::string shell_quote(const std::string& s) {
  std::string o = "'";
  for (char c : s) {
    if (c == '\'') o += "'\\''";
    else o += c;
  }
  return o + "'";
}

}  // namespace

void write_plots(const EvaluationResult& result, const fs::path& dir, const std::string& gnuplot) {
  const fs::path pdir = dir / "plots";
  fs::create_directories(pdir);
  for (const auto& rr : result.ratings) {
    const std::string base = rr.def.name;
    const fs::path band = pdir / (base + "_corridor.dat");
    const fs::path ref = pdir / (base + "_reference.dat");
    const fs::path model = pdir / (base + "_model.dat");
    write_xy(band, corridor_polygon(rr.corridor));
    write_xy(ref, rr.reference);
    write_xy(model, rr.model);
    // two title lines: gnuplot turns the escape \n inside a double-quoted string into a newline
    const std::string title = gp_escape(rr.def.title) + "\\nISO/TS 18571 R = " + fixed(rr.iso.overall, 3) + " (" +
                              rr.iso.grade + ")    CORA = " + fixed(rr.cora.overall, 3) + "    inside corridor " +
                              fixed(100.0 * rr.inside_fraction, 0) + " %";
    const std::string xl = rr.def.x_label + " [" + rr.x_unit + "]";
    const std::string yl = rr.def.y_label + " [" + rr.y_unit + "]";
    const std::string ref_title = rr.reference_is_mean ? rr.corridor.mean_name : std::string("corridor mid-line");
    std::ostringstream gp;
    gp << "# gnuplot script written by hbm-corridors for rating '" << base << "'\n"
       << "set encoding utf8\n"
       << "set title \"" << title << "\" noenhanced font \",15\"\n"
       << "set xlabel \"" << gp_escape(xl) << "\" noenhanced font \",14\"\n"
       << "set ylabel \"" << gp_escape(yl) << "\" noenhanced font \",14\"\n"
       << "set tics font \",12\"\n"
       << "set key top right box opaque font \",12\" spacing 1.2\n"
       << "set grid lc rgb '#d0d0d0'\n"
       << "set border lw 1.2\n"
       << "set xrange [*:*]\nset yrange [*:*]\nset offsets 0, 0, graph 0.12, 0\n";
    const std::string plot =
        "plot '" + band.filename().string() + "' using 1:2 with filledcurves closed fs transparent solid 0.35 noborder lc rgb '#7fa7d9' title 'PMHS corridor', \\\n"
        "     '" + band.filename().string() + "' using 1:2 with lines lw 1 lc rgb '#5d84b8' notitle, \\\n"
        "     '" + ref.filename().string() + "' using 1:2 with lines dt 2 lw 2.5 lc rgb '#202020' title '" + ref_title + "', \\\n"
        "     '" + model.filename().string() + "' using 1:2 with lines lw 3 lc rgb '#d62728' title 'model'\n";
    gp << "set terminal pngcairo size 1200,850 enhanced font 'DejaVu Sans,12' linewidth 1.3\n"
       << "set output '" << base << ".png'\n"
       << plot
       << "set terminal svg size 1200,850 enhanced font 'DejaVu Sans,12' linewidth 1.3 background rgb 'white'\n"
       << "set output '" << base << ".svg'\n"
       << "replot\nset output\n";
    const fs::path script = pdir / (base + ".gp");
    {
      std::ofstream f(script);
      f << gp.str();
      if (!f) throw std::runtime_error("cannot write " + script.string());
    }
    // run in the plot folder: the script names its files relative to it, so the report
    // folder can be moved (it is written under a temporary name and renamed at the end)
    const std::string cmd = "cd " + shell_quote(pdir.string()) + " && " + shell_quote(gnuplot) + " " +
                            shell_quote(base + ".gp") + " 2> " + shell_quote(base + ".gnuplot.log");
    const int rc = std::system(cmd.c_str());
    if (rc != 0) {
      std::ifstream log(pdir / (base + ".gnuplot.log"));
      std::stringstream ls;
      ls << log.rdbuf();
      throw std::runtime_error("gnuplot failed (exit " + std::to_string(rc) + ") on " + script.string() + ": " + ls.str());
    }
    if (!fs::exists(pdir / (base + ".png")) || !fs::exists(pdir / (base + ".svg")))
      throw std::runtime_error("gnuplot did not write the plots of " + base);
    fs::remove(pdir / (base + ".gnuplot.log"));
  }
}

}  // namespace hbm::corridors
