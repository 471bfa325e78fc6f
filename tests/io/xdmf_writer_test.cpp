// Tests of the XDMF sidecars (xdmf_writer.hpp) on the files the writers make:
// the XML is well-formed, every HDF reference names the file beside it and
// an existing dataset whose shape and type the DataItem declares, the grids
// carry the right topology and spacing, and an output named *.xdmf is
// refused. The reader test with VTK's vtkXdmfReader is
// tests/python/test_xdmf_sidecars.py.
#include "halfspace/io/xdmf_writer.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <hdf5.h>

#include <cstdint>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "halfspace/error.hpp"
#include "halfspace/io/height_map_writer.hpp"
#include "halfspace/io/result_writer.hpp"
#include "halfspace/io/sweep_writer.hpp"
#include "io/hdf5_test_support.hpp"

namespace halfspace::io {
namespace {

namespace fs = std::filesystem;
using test::TempDir;

// A minimal XML element tree: enough to check the sidecars' structure.
struct Element {
  std::string name;
  std::map<std::string, std::string> attributes;
  std::string text;
  std::vector<std::unique_ptr<Element>> children;

  std::vector<const Element*> all(const std::string& wanted) const {
    std::vector<const Element*> found;
    for (const auto& child : children) {
      if (child->name == wanted) found.push_back(child.get());
      for (const Element* deeper : child->all(wanted)) found.push_back(deeper);
    }
    return found;
  }
  const Element& child(const std::string& wanted) const {
    for (const auto& c : children) {
      if (c->name == wanted) return *c;
    }
    throw std::runtime_error("no <" + wanted + "> in <" + name + ">");
  }
};

// Parses `xml` (declaration and DOCTYPE skipped); throws on an unbalanced
// or unterminated tag, so a malformed sidecar fails the test.
std::unique_ptr<Element> parse(const std::string& xml) {
  auto document = std::make_unique<Element>();
  std::vector<Element*> open{document.get()};
  std::size_t at = 0;
  while (at < xml.size()) {
    const std::size_t tag = xml.find('<', at);
    if (tag == std::string::npos) break;
    open.back()->text += xml.substr(at, tag - at);
    const std::size_t end = xml.find('>', tag);
    if (end == std::string::npos) throw std::runtime_error("unterminated tag");
    const std::string inside = xml.substr(tag + 1, end - tag - 1);
    at = end + 1;
    if (inside.starts_with('?') || inside.starts_with('!')) continue;
    if (inside.starts_with('/')) {
      if (open.size() < 2 || open.back()->name != inside.substr(1)) throw std::runtime_error("unbalanced </" + inside);
      open.pop_back();
      continue;
    }
    const bool empty = inside.ends_with('/');
    std::istringstream words(empty ? inside.substr(0, inside.size() - 1) : inside);
    auto element = std::make_unique<Element>();
    words >> element->name;
    std::string rest((std::istreambuf_iterator<char>(words)), std::istreambuf_iterator<char>());
    for (std::size_t a = rest.find('='); a != std::string::npos; a = rest.find('=')) {
      std::string key = rest.substr(0, a);
      key.erase(0, key.find_first_not_of(' '));
      const std::size_t quote = rest.find('"', a);
      const std::size_t close = rest.find('"', quote + 1);
      if (quote != a + 1 || close == std::string::npos) throw std::runtime_error("bad attribute in <" + inside);
      element->attributes[key] = rest.substr(quote + 1, close - quote - 1);
      rest = rest.substr(close + 1);
    }
    Element* raw = element.get();
    open.back()->children.push_back(std::move(element));
    if (!empty) open.push_back(raw);
  }
  if (open.size() != 1) throw std::runtime_error("unclosed <" + open.back()->name + ">");
  return document;
}

std::vector<hsize_t> numbers(const std::string& text) {
  std::vector<hsize_t> values;
  std::istringstream in(text);
  for (hsize_t v = 0; in >> v;) values.push_back(v);
  return values;
}

std::unique_ptr<Element> read_sidecar(const fs::path& path) {
  std::ifstream in(path);
  EXPECT_TRUE(in) << path;
  std::stringstream text;
  text << in.rdbuf();
  return parse(text.str());
}

// Every HDF DataItem names `h5` by its file name and an existing dataset
// with as many values as it declares, the same extents once the leading
// ones are dropped, and the declared type. Returns the dataset paths.
std::vector<std::string> check_references(const Element& xdmf, const fs::path& h5) {
  const test::H5 file = test::open_file(h5);
  std::vector<std::string> paths;
  for (const Element* item : xdmf.all("DataItem")) {
    if (item->attributes.at("Format") != "HDF") continue;
    const std::string& reference = item->text;
    const std::size_t colon = reference.find(':');
    EXPECT_EQ(reference.substr(0, colon), h5.filename().string());
    const std::string path = reference.substr(colon + 1);
    paths.push_back(path);
    std::vector<hsize_t> declared = numbers(item->attributes.at("Dimensions"));
    while (declared.size() > 1 && declared.front() == 1) declared.erase(declared.begin());
    std::vector<hsize_t> stored = test::dataset_shape(file.get(), path);
    while (stored.size() > 1 && stored.front() == 1) stored.erase(stored.begin());
    // The one 1D exception: a line's values "1 1 n" are stored as (n).
    EXPECT_EQ(declared, stored) << path;
    const test::StoredType type = test::dataset_type(file.get(), path);
    const std::string& number_type = item->attributes.at("NumberType");
    if (number_type == "UChar") {
      EXPECT_EQ(type.type_class, H5T_INTEGER) << path;
      EXPECT_EQ(type.size, 1U) << path;
      EXPECT_EQ(item->attributes.at("Precision"), "1");
    } else {
      EXPECT_EQ(number_type, "Float") << path;
      EXPECT_EQ(type.type_class, H5T_FLOAT) << path;
      EXPECT_EQ(type.size, 8U) << path;
      EXPECT_EQ(item->attributes.at("Precision"), "8");
    }
  }
  return paths;
}

SolveResult make_result(const Grid& grid, double scale) {
  const auto n = static_cast<Eigen::Index>(grid.size());
  SolveResult result;
  result.solver = "test";
  result.pressure = Eigen::ArrayXd::LinSpaced(n, 0.0, scale);
  result.gap = Eigen::ArrayXd::LinSpaced(n, 1e-9, 0.0);
  result.displacement = Eigen::ArrayXd::Constant(n, 1e-8);
  return result;
}

TEST(XdmfWriterTest, ResultSidecarDescribesEveryFieldOnTheUniformGrid) {
  const TempDir dir;
  const Grid grid = Grid::plane(6, 4, 2e-6, 3e-6, Boundary::periodic);
  SolveResult result = make_result(grid, 1e6);
  result.hardness = 5e5;  // adds plastic and plastic_displacement
  write_result(dir / "r.h5", grid, std::vector<double>(grid.size(), 0.0), result, ResultMetadata{});
  const auto xdmf = read_sidecar(dir / "r.xdmf");
  const Element& root = xdmf->child("Xdmf");
  EXPECT_EQ(root.attributes.at("Version"), "2.0");
  const std::vector<const Element*> grids = root.all("Grid");
  ASSERT_EQ(grids.size(), 1U);
  const Element& topology = grids[0]->child("Topology");
  EXPECT_EQ(topology.attributes.at("TopologyType"), "3DCoRectMesh");
  EXPECT_EQ(topology.attributes.at("Dimensions"), "2 5 7");  // nodes of one layer of 4 x 6 cells
  const Element& geometry = grids[0]->child("Geometry");
  EXPECT_EQ(geometry.attributes.at("GeometryType"), "ORIGIN_DXDYDZ");
  // z, y, x: cells centred on x = i dx, y = j dy.
  EXPECT_EQ(geometry.children.at(0)->text, "0 -1.5e-06 -1e-06");
  EXPECT_EQ(geometry.children.at(1)->text, "2e-06 3e-06 2e-06");
  std::vector<std::string> names;
  for (const Element* attribute : grids[0]->all("Attribute")) {
    names.push_back(attribute->attributes.at("Name"));
    EXPECT_EQ(attribute->attributes.at("Center"), "Cell");
  }
  EXPECT_EQ(names, (std::vector<std::string>{"contact", "displacement", "gap", "height", "plastic",
                                             "plastic_displacement", "pressure"}));
  EXPECT_EQ(check_references(*xdmf, dir / "r.h5").size(), 7U);
  // residual_history is not a field: not in the sidecar.
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"r.h5", "r.xdmf"}));
}

TEST(XdmfWriterTest, OneDimensionalResultIsALineOfNodes) {
  const TempDir dir;
  const Grid grid = Grid::line(9, 0.5e-6, Boundary::free);
  write_result(dir / "line.h5", grid, std::vector<double>(grid.size(), 0.0), make_result(grid, 1e3), ResultMetadata{});
  const auto xdmf = read_sidecar(dir / "line.xdmf");
  const Element& grid_element = *xdmf->all("Grid").at(0);
  EXPECT_EQ(grid_element.child("Topology").attributes.at("Dimensions"), "1 1 9");
  EXPECT_EQ(grid_element.child("Geometry").children.at(0)->text, "0 0 0");
  for (const Element* attribute : grid_element.all("Attribute")) EXPECT_EQ(attribute->attributes.at("Center"), "Node");
  EXPECT_EQ(check_references(*xdmf, dir / "line.h5").size(), 5U);
}

TEST(XdmfWriterTest, SweepIsATemporalCollectionOfItsSteps) {
  const TempDir dir;
  const Grid grid = Grid::plane(5, 3, 1e-6, 1e-6, Boundary::periodic);
  std::vector<analysis::SweepStep> steps(3);
  for (std::size_t k = 0; k < steps.size(); ++k) {
    steps[k].loading = Loading::force(double(k + 1));
    steps[k].result = make_result(grid, double(k + 1));
  }
  write_sweep_result(dir / "s.h5", grid, std::vector<double>(grid.size(), 0.0), steps, ResultMetadata{});
  const auto xdmf = read_sidecar(dir / "s.xdmf");
  const Element& collection = *xdmf->all("Grid").at(0);
  EXPECT_EQ(collection.attributes.at("GridType"), "Collection");
  EXPECT_EQ(collection.attributes.at("CollectionType"), "Temporal");
  ASSERT_EQ(collection.children.size(), 3U);
  for (std::size_t k = 0; k < 3; ++k) {
    const Element& step = *collection.children[k];
    EXPECT_EQ(step.child("Time").attributes.at("Value"), fmt::format("{}", k));
    std::vector<std::string> references;
    for (const Element* item : step.all("DataItem")) {
      if (item->attributes.at("Format") == "HDF") references.push_back(item->text);
    }
    EXPECT_EQ(references, (std::vector<std::string>{"s.h5:/height", fmt::format("s.h5:/steps/00{}/contact", k),
                                                    fmt::format("s.h5:/steps/00{}/displacement", k),
                                                    fmt::format("s.h5:/steps/00{}/gap", k),
                                                    fmt::format("s.h5:/steps/00{}/pressure", k)}));
  }
  EXPECT_EQ(check_references(*xdmf, dir / "s.h5").size(), 15U);
}

TEST(XdmfWriterTest, StressVolumeIsARectilinearGridBelowTheSurface) {
  const TempDir dir;
  const fs::path h5 = dir / "stress.h5";
  {
    const test::H5 file = test::create_file(h5);
    test::add_double_dataset(file.get(), "pressure", {2, 3}, std::vector<double>(6, 1.0));
    const test::H5 group(H5Gcreate2(file.get(), "stress", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose, "group");
    test::add_double_dataset(group.get(), "depths", {3}, {1e-6, 2.5e-6, 1e-5});
    test::add_double_dataset(group.get(), "von_mises", {3, 2, 3}, std::vector<double>(18, 2.0));
    test::add_double_dataset(group.get(), "other_shape", {2, 2, 3}, std::vector<double>(12, 2.0));
  }
  write_xdmf_sidecar(h5, Grid::plane(3, 2, 1e-6, 2e-6, Boundary::free));
  const auto xdmf = read_sidecar(dir / "stress.xdmf");
  const std::vector<const Element*> grids = xdmf->all("Grid");
  ASSERT_EQ(grids.size(), 2U);
  const Element& stress = *grids[1];
  EXPECT_EQ(stress.attributes.at("Name"), "stress");
  EXPECT_EQ(stress.child("Topology").attributes.at("TopologyType"), "3DRectMesh");
  EXPECT_EQ(stress.child("Topology").attributes.at("Dimensions"), "3 2 3");
  const Element& geometry = stress.child("Geometry");
  EXPECT_EQ(geometry.attributes.at("GeometryType"), "VXVYVZ");
  EXPECT_EQ(geometry.children.at(0)->text, "0 1e-06 2e-06");
  EXPECT_EQ(geometry.children.at(1)->text, "0 2e-06");
  EXPECT_EQ(geometry.children.at(2)->text, "-1e-06 -2.5e-06 -1e-05");  // z = -depth
  const std::vector<const Element*> attributes = stress.all("Attribute");
  ASSERT_EQ(attributes.size(), 1U);  // not the dataset of another shape
  EXPECT_EQ(attributes[0]->attributes.at("Name"), "von_mises");
  EXPECT_EQ(attributes[0]->attributes.at("Center"), "Node");
  EXPECT_EQ(check_references(*xdmf, h5), (std::vector<std::string>{"/pressure", "/stress/von_mises"}));
}

TEST(XdmfWriterTest, HeightMapGetsItsSidecar) {
  const TempDir dir;
  const Grid grid = Grid::plane(4, 4, 1e-6, 1e-6, Boundary::periodic);
  write_height_map(dir / "h.h5", grid, std::vector<double>(16, 1e-7), HeightMapMetadata{});
  const auto xdmf = read_sidecar(dir / "h.xdmf");
  EXPECT_EQ(check_references(*xdmf, dir / "h.h5"), (std::vector<std::string>{"/height"}));
}

TEST(XdmfWriterTest, RefusesAnOutputNamedLikeItsSidecar) {
  const TempDir dir;
  const Grid grid = Grid::plane(4, 4, 1e-6, 1e-6, Boundary::periodic);
  try {
    write_height_map(dir / "h.xdmf", grid, std::vector<double>(16, 1e-7), HeightMapMetadata{});
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("ends in .xdmf"), std::string::npos) << error.what();
  }
}

TEST(XdmfWriterTest, AFileWithoutFieldsOfTheGridIsAnErrorNamingIt) {
  const TempDir dir;
  const fs::path h5 = dir / "odd.h5";
  {
    const test::H5 file = test::create_file(h5);
    test::add_double_dataset(file.get(), "height", {3, 3}, std::vector<double>(9, 0.0));
  }
  try {
    (void)xdmf_sidecar_text(h5, Grid::plane(4, 4, 1e-6, 1e-6, Boundary::periodic));
    ADD_FAILURE() << "no FileError";
  } catch (const FileError& error) {
    EXPECT_NE(std::string(error.what()).find("odd.h5"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("no dataset shaped like the grid"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace halfspace::io
