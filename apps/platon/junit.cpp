#include "junit.h"

#include <stdexcept>
#include <tinyxml2.h>

#include "platon/core/visible_text.h"
#include "platon/files/read_file.h"
#include "platon/files/write_file.h"

namespace platon::app {

bool writeJunit(const std::string& path, const JunitReport& report) {
  using tinyxml2::XMLElement;
  tinyxml2::XMLDocument doc;
  doc.InsertEndChild(doc.NewDeclaration(R"(xml version="1.0" encoding="UTF-8")"));
  XMLElement* suite = doc.NewElement("testsuite");
  doc.InsertEndChild(suite);
  int failures = 0;
  for (const JunitCase& c : report.cases) failures += c.passed ? 0 : 1;
  suite->SetAttribute("name", "platon scenarios");
  suite->SetAttribute("tests", static_cast<int64_t>(report.cases.size()));
  suite->SetAttribute("failures", failures);
  suite->SetAttribute("time", report.seconds);
  if (!report.properties.empty()) {
    XMLElement* properties = suite->InsertNewChildElement("properties");
    for (const auto& [name, value] : report.properties) {
      XMLElement* property = properties->InsertNewChildElement("property");
      property->SetAttribute("name", core::visibleText(name, true).c_str());
      property->SetAttribute("value", core::visibleText(value, true).c_str());
    }
  }
  for (const JunitCase& c : report.cases) {
    XMLElement* testcase = suite->InsertNewChildElement("testcase");
    testcase->SetAttribute("classname", "scenario");
    testcase->SetAttribute("name", core::visibleText(c.name, true).c_str());
    testcase->SetAttribute("time", c.seconds);
    if (c.passed) continue;
    const std::string text = core::visibleText(c.message, true);
    XMLElement* failure = testcase->InsertNewChildElement("failure");
    failure->SetAttribute("message", text.substr(0, text.find('\n')).c_str());
    failure->SetText(text.c_str());
  }
  tinyxml2::XMLPrinter printer;
  doc.Print(&printer);
  return files::saveWhole(path, std::string(printer.CStr(), static_cast<size_t>(printer.CStrSize() - 1)),
                          "the JUnit report")
      .empty();
}

JunitReport readJunit(const std::string& path) {
  const std::string text = files::readBoundedFile(path, size_t{256} << 20);
  tinyxml2::XMLDocument doc;
  if (doc.Parse(text.data(), text.size()) != tinyxml2::XML_SUCCESS)
    throw std::runtime_error(path + ":" + std::to_string(doc.ErrorLineNum()) + ": not XML: " + doc.ErrorStr());
  const tinyxml2::XMLElement* root = doc.RootElement();
  const tinyxml2::XMLElement* first = nullptr;
  if (root && std::string(root->Name()) == "testsuite") first = root;
  if (root && std::string(root->Name()) == "testsuites") first = root->FirstChildElement("testsuite");
  if (!first) throw std::runtime_error(path + ": not a JUnit report (no <testsuite>)");
  JunitReport report;
  if (const tinyxml2::XMLElement* properties = first->FirstChildElement("properties"))
    for (const tinyxml2::XMLElement* p = properties->FirstChildElement("property"); p;
         p = p->NextSiblingElement("property"))
      if (const char* name = p->Attribute("name"))
        report.properties[name] = p->Attribute("value") ? p->Attribute("value") : "";
  for (const tinyxml2::XMLElement* suite = first; suite; suite = suite->NextSiblingElement("testsuite")) {
    report.seconds += suite->DoubleAttribute("time");
    for (const tinyxml2::XMLElement* c = suite->FirstChildElement("testcase"); c;
         c = c->NextSiblingElement("testcase")) {
      JunitCase one;
      const char* name = c->Attribute("name");
      if (!name) throw std::runtime_error(path + ":" + std::to_string(c->GetLineNum()) + ": a <testcase> with no name");
      one.name = name;
      one.seconds = c->DoubleAttribute("time");
      const tinyxml2::XMLElement* failure = c->FirstChildElement("failure");
      if (!failure) failure = c->FirstChildElement("error");
      if (failure) {
        one.passed = false;
        one.message = failure->GetText() ? failure->GetText()
                                         : (failure->Attribute("message") ? failure->Attribute("message") : "");
      }
      report.cases.push_back(std::move(one));
    }
  }
  return report;
}

}  // namespace platon::app
