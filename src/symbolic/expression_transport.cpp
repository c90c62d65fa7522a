// Expressions as bytes between forked processes.
#include "unidyn/symbolic/expression_transport.hpp"

#include <sstream>

namespace unidyn {
namespace {

using GiNaC::is_a;
using GiNaC::is_exactly_a;

// The kinds of node, each written as its byte and then its fields.
enum class Node : char {
  symbol = 's',
  number = 'n',
  sum = '+',
  product = '*',
  power = '^',
  function = 'f'
};

void put_count(std::string& bytes, std::uint64_t n) {
  bytes.append(reinterpret_cast<const char*>(&n), sizeof n);
}

std::uint64_t take_count(std::string_view& bytes) {
  std::uint64_t n;
  if (bytes.size() < sizeof n) throw Untransportable("an expression's bytes end early");
  std::copy_n(bytes.data(), sizeof n, reinterpret_cast<char*>(&n));
  bytes.remove_prefix(sizeof n);
  return n;
}

// The writer: each node's place in the post-order, shared nodes once.
class Writer {
 public:
  Writer(const SymbolTable& symbols, std::string& bytes) : symbols_(symbols), bytes_(bytes) {}

  std::uint64_t node(const Expr& e) {
    if (const auto found = written_.find(&GiNaC::ex_to<GiNaC::basic>(e)); found != written_.end())
      return found->second;
    std::vector<std::uint64_t> children;
    for (std::size_t i = 0; i < e.nops(); ++i) children.push_back(node(e.op(i)));
    if (is_a<GiNaC::symbol>(e)) {
      const std::int64_t place = symbols_.place(e);
      if (place < 0) throw Untransportable("a symbol outside the table: " + text(e));
      bytes_ += char(Node::symbol);
      put_count(bytes_, std::uint64_t(place));
    } else if (is_exactly_a<GiNaC::numeric>(e)) {
      if (!e.info(GiNaC::info_flags::rational)) {
        throw Untransportable("a number that is not rational: " + text(e));
      }
      const std::string digits = text(e);
      bytes_ += char(Node::number);
      put_count(bytes_, digits.size());
      bytes_ += digits;
    } else if (is_exactly_a<GiNaC::add>(e) || is_exactly_a<GiNaC::mul>(e) ||
               is_exactly_a<GiNaC::power>(e)) {
      bytes_ += char(is_exactly_a<GiNaC::add>(e)   ? Node::sum
                     : is_exactly_a<GiNaC::mul>(e) ? Node::product
                                                   : Node::power);
      put_children(children);
    } else if (is_exactly_a<GiNaC::function>(e)) {
      bytes_ += char(Node::function);
      put_count(bytes_, GiNaC::ex_to<GiNaC::function>(e).get_serial());
      put_children(children);
    } else {
      throw Untransportable("an expression of a class that does not travel: " + text(e));
    }
    written_.emplace(&GiNaC::ex_to<GiNaC::basic>(e), count_);
    alive_.push_back(e);
    return count_++;
  }

 private:
  static std::string text(const Expr& e) {
    std::ostringstream out;
    out << e;
    return out.str();
  }
  void put_children(const std::vector<std::uint64_t>& children) {
    put_count(bytes_, children.size());
    for (const std::uint64_t c : children) put_count(bytes_, c);
  }

  const SymbolTable& symbols_;
  std::string& bytes_;
  std::unordered_map<const GiNaC::basic*, std::uint64_t> written_;
  // the nodes met (a sum's terms are made anew by op(): kept, their addresses are not reused)
  std::vector<Expr> alive_;
  std::uint64_t count_ = 0;
};

}  // namespace

SymbolTable::SymbolTable(const std::vector<Expr>& expressions) {
  // each node once (a shared subexpression is walked once), the nodes kept while walking
  std::unordered_map<const GiNaC::basic*, bool> seen;
  std::vector<Expr> alive;
  const auto walk = [&](const auto& self, const Expr& e) -> void {
    if (!seen.emplace(&GiNaC::ex_to<GiNaC::basic>(e), true).second) return;
    alive.push_back(e);
    if (is_a<GiNaC::symbol>(e)) {
      if (places_.emplace(e, symbols_.size()).second) symbols_.push_back(e);
      return;
    }
    for (std::size_t i = 0; i < e.nops(); ++i) self(self, e.op(i));
  };
  for (const Expr& e : expressions) walk(walk, e);
}

std::int64_t SymbolTable::place(const Expr& s) const {
  const auto found = places_.find(s);
  return found == places_.end() ? -1 : std::int64_t(found->second);
}

void write_expression(const Expr& e, const SymbolTable& symbols, std::string& bytes) {
  // the nodes apart first, then their count: nothing appended when a node does not travel
  std::string nodes;
  Writer writer(symbols, nodes);
  const std::uint64_t count = writer.node(e) + 1;
  put_count(bytes, count);
  bytes += nodes;
}

Expr read_expression(std::string_view& bytes, const SymbolTable& symbols) {
  const std::uint64_t count = take_count(bytes);
  if (count == 0 || count > bytes.size()) throw Untransportable("an expression of no nodes");
  std::vector<Expr> nodes;
  nodes.reserve(count);
  // the children named by a node: earlier nodes
  const auto children = [&] {
    const std::uint64_t n = take_count(bytes);
    if (n > bytes.size()) throw Untransportable("an expression's bytes end early");
    GiNaC::exvector parts;
    for (std::uint64_t k = 0; k < n; ++k) {
      const std::uint64_t place = take_count(bytes);
      if (place >= nodes.size()) throw Untransportable("a node names a later one");
      parts.push_back(nodes[place]);
    }
    return parts;
  };
  while (nodes.size() < count) {
    if (bytes.empty()) throw Untransportable("an expression's bytes end early");
    const Node kind = Node(bytes.front());
    bytes.remove_prefix(1);
    switch (kind) {
      case Node::symbol: {
        const std::uint64_t place = take_count(bytes);
        if (place >= symbols.size()) throw Untransportable("a symbol outside the table");
        nodes.push_back(symbols.symbol(place));
        break;
      }
      case Node::number: {
        const std::uint64_t n = take_count(bytes);
        if (n > bytes.size()) throw Untransportable("an expression's bytes end early");
        nodes.push_back(GiNaC::numeric(std::string(bytes.substr(0, n)).c_str()));
        bytes.remove_prefix(n);
        break;
      }
      case Node::sum:
        nodes.push_back(GiNaC::dynallocate<GiNaC::add>(children()));
        break;
      case Node::product:
        nodes.push_back(GiNaC::dynallocate<GiNaC::mul>(children()));
        break;
      case Node::power: {
        const GiNaC::exvector parts = children();
        if (parts.size() != 2) throw Untransportable("a power of other than two parts");
        nodes.push_back(GiNaC::pow(parts[0], parts[1]));
        break;
      }
      case Node::function: {
        const std::uint64_t serial = take_count(bytes);
        nodes.push_back(GiNaC::function(unsigned(serial), children()));
        break;
      }
      default:
        throw Untransportable("not a node");
    }
  }
  return nodes.back();
}

}  // namespace unidyn
