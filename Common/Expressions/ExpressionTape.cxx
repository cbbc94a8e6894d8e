// The tape builder (ExpressionTape.h): orders the live nodes of the graph by
// the lowest derivative order that needs them, fuses small products into the
// sums that use them, allocates registers, encodes each node as one
// instruction, and fuses a sum read only by its exponential (every Gaussian
// bump) into one instruction.
#include "ExpressionTape.h"

#include "DerivativeLayout.h"
#include "ExpressionError.h"

#include <algorithm>
#include <cstddef>
#include <utility>

namespace riemann
{
namespace expression
{
namespace
{
/// One step of the instruction sequence.
struct Item
{
  int Node;   // >= 0: compute this node
  int Output; // else: store this output
};

/// The operands of a node: Lin, one group per term (the factors of a product
/// fused into the sum, or the term alone); others, one group per argument.
using OperandGroups = std::vector<std::vector<int>>;

/// Calls read(register) for every register `in` reads.
template <class Read>
void ForEachRead(const Instruction& in, const ExpressionTape& tape, Read read)
{
  auto operandList = [&](int count)
  {
    for (int i = 0; i < count; ++i)
    {
      read(tape.Operands[static_cast<std::size_t>(in.A + i)]);
    }
  };
  switch (in.Operation)
  {
    case Code::Const:
    case Code::StoreConst:
      break;
    case Code::Lin:
    case Code::Mul:
    case Code::ExpLin:
      operandList(in.N);
      break;
    case Code::LinP2:
      operandList(2 * in.N);
      break;
    case Code::LinP3:
      operandList(3 * in.N);
      break;
    case Code::Add2:
    case Code::Sub2:
    case Code::Mul2:
    case Code::Div:
    case Code::Pow:
    case Code::Atan2:
      read(in.A);
      read(in.B);
      break;
    default: // one register argument, stores included
      read(in.A);
      break;
  }
}

/// True if register `reg`, written by instruction `first`, is read by
/// instruction first + 1 and by no later one before it is written again.
bool ReadOnlyByNext(const ExpressionTape& tape, std::size_t first, int reg)
{
  if (tape.Instructions[first + 1].D == reg) // the reader overwrites it (exp(x) in place)
  {
    return true;
  }
  for (std::size_t i = first + 2; i < tape.Instructions.size(); ++i)
  {
    const Instruction& in = tape.Instructions[i];
    bool read = false;
    ForEachRead(in, tape, [&](int r) { read = read || r == reg; });
    if (read)
    {
      return false;
    }
    const bool writes = in.Operation != Code::Store && in.Operation != Code::StoreScaled &&
      in.Operation != Code::StoreConst;
    if (writes && in.D == reg)
    {
      return true;
    }
  }
  return true;
}

/**
 * Replaces Lin + Exp by ExpLin where the sum is read only by its exponential:
 * one dispatch and one register round trip less per Gaussian bump
 * exp(-|p - c|^2 / 2 s^2), whose other parts (the shifts p - c and their
 * squares) are shared with the derivatives. The fused instruction does the
 * same operations in the same order: results are unchanged.
 */
void FuseSumsIntoExponentials(ExpressionTape& tape)
{
  std::vector<Instruction>& code = tape.Instructions;
  std::vector<bool> removed(code.size(), false);
  for (std::size_t i = 0; i + 1 < code.size(); ++i)
  {
    const Instruction& sum = code[i];
    Instruction& exponential = code[i + 1];
    if (sum.Operation != Code::Lin || exponential.Operation != Code::Exp ||
      exponential.A != sum.D || !ReadOnlyByNext(tape, i, sum.D))
    {
      continue;
    }
    const int destination = exponential.D;
    exponential = sum;
    exponential.Operation = Code::ExpLin;
    exponential.D = destination;
    removed[i] = true;
    --tape.Operations;
  }
  // Compact, and move each End[] to the same place among the kept ones.
  std::vector<int> kept(code.size() + 1, 0);
  std::size_t out = 0;
  for (std::size_t i = 0; i < code.size(); ++i)
  {
    kept[i] = static_cast<int>(out);
    if (!removed[i])
    {
      code[out++] = code[i];
    }
  }
  kept[code.size()] = static_cast<int>(out);
  code.resize(out);
  for (int& end : tape.End)
  {
    end = kept[static_cast<std::size_t>(end)];
  }
}

class TapeBuilder
{
public:
  TapeBuilder(const ExpressionGraph& graph, int order, int inputs)
    : Graph(graph)
    , Order(order)
    , Inputs(inputs)
    , One(inputs)
    , PerSource(DerivativeLayout::OutputsPerSource(order))
    , Count(graph.Nodes.size())
  {
  }

  ExpressionTape Build()
  {
    this->FindLevelsAndUses();
    this->FuseProductsIntoSums();
    this->Schedule();
    this->FindLastUses();
    this->EmitInstructions();
    FuseSumsIntoExponentials(this->Tape);
    return std::move(this->Tape);
  }

private:
  const ExpressionGraph& Graph;
  const int Order;
  /// Registers 0 .. Inputs - 1 hold the inputs; register One holds 1.0.
  const int Inputs;
  const int One;
  const int PerSource;
  const std::size_t Count;

  /// Lowest derivative order of an output needing the node (4: dead).
  std::vector<int> Level;
  /// Users of the node among live nodes and outputs.
  std::vector<int> Uses;
  /// The node is a product computed inside the sum that uses it.
  std::vector<char> Fused;
  /// Per live node, its operand groups.
  std::vector<OperandGroups> Groups;
  /// Nodes of level n, then the stores of order n, for n = 0 .. Order.
  std::vector<Item> Items;
  /// Position in Items of the last read of each node.
  std::vector<int> LastUse;
  /// Register of each computed node.
  std::vector<int> Reg;
  std::vector<int> FreeRegisters;
  /// Nodes whose registers the current item released.
  std::vector<int> Released;
  int Registers = 0;
  ExpressionTape Tape;

  /// Levels (operands have a level at most their users') and use counts.
  void FindLevelsAndUses()
  {
    this->Level.assign(this->Count, 4);
    this->Uses.assign(this->Count, 0);
    for (std::size_t o = 0; o < this->Graph.Outputs.size(); ++o)
    {
      const int id = this->Graph.Outputs[o].Id;
      if (id >= 0)
      {
        this->Level[id] = std::min(this->Level[id], OutputOrder(o, this->PerSource));
        ++this->Uses[id];
      }
    }
    for (std::size_t i = this->Count; i-- > 0;)
    {
      if (this->Level[i] > this->Order)
      {
        continue;
      }
      for (int a : this->Graph.Nodes[i].Args)
      {
        this->Level[a] = std::min(this->Level[a], this->Level[i]);
        ++this->Uses[a];
      }
    }
  }

  /// The factors of a product (of at most 3 factors, or a square) that its
  /// only user, a sum, can compute itself; else the node alone.
  std::vector<int> Factors(int id) const
  {
    const Node& n = this->Graph.Nodes[id];
    if (id >= this->Inputs && this->Uses[id] == 1 && n.Operation == Op::Mul && n.Args.size() <= 3)
    {
      return n.Args;
    }
    if (id >= this->Inputs && this->Uses[id] == 1 && n.Operation == Op::Square)
    {
      return { n.Args[0], n.Args[0] };
    }
    return { id };
  }

  /// Fusion: a small product used only by one sum becomes a term of that
  /// sum, c * r[a] * r[b] (* r[c]): derivatives of sums are sums of
  /// products, and this halves the instructions dispatched.
  void FuseProductsIntoSums()
  {
    this->Fused.assign(this->Count, 0);
    this->Groups.assign(this->Count, OperandGroups());
    for (std::size_t i = static_cast<std::size_t>(this->Inputs); i < this->Count; ++i)
    {
      if (this->Level[i] > this->Order)
      {
        continue;
      }
      const Node& node = this->Graph.Nodes[i];
      for (int a : node.Args)
      {
        if (node.Operation == Op::Lin)
        {
          this->Groups[i].push_back(this->Factors(a));
          if (this->Groups[i].back().size() > 1)
          {
            this->Fused[a] = 1;
          }
        }
        else
        {
          this->Groups[i].push_back({ a });
        }
      }
    }
  }

  /// Items and Tape.End: the outputs up to order n need the first End[n].
  void Schedule()
  {
    for (int n = 0; n <= this->Order; ++n)
    {
      for (std::size_t i = static_cast<std::size_t>(this->Inputs); i < this->Count; ++i)
      {
        if (this->Level[i] == n && !this->Fused[i])
        {
          this->Items.push_back({ static_cast<int>(i), -1 });
        }
      }
      for (std::size_t o = 0; o < this->Graph.Outputs.size(); ++o)
      {
        if (OutputOrder(o, this->PerSource) == n)
        {
          this->Items.push_back({ -1, static_cast<int>(o) });
        }
      }
      this->Tape.End[n] = static_cast<int>(this->Items.size());
    }
  }

  void FindLastUses()
  {
    this->LastUse.assign(this->Count, -1);
    for (std::size_t p = 0; p < this->Items.size(); ++p)
    {
      const Item& item = this->Items[p];
      if (item.Node >= 0)
      {
        for (const std::vector<int>& g : this->Groups[item.Node])
        {
          for (int a : g)
          {
            this->LastUse[a] = static_cast<int>(p);
          }
        }
      }
      else if (this->Graph.Outputs[item.Output].Id >= 0)
      {
        this->LastUse[this->Graph.Outputs[item.Output].Id] = static_cast<int>(p);
      }
    }
  }

  /// One instruction per item, registers allocated on the way.
  void EmitInstructions()
  {
    this->Reg.assign(this->Count, -1);
    for (int i = 0; i < this->Inputs; ++i)
    {
      this->Reg[i] = i;
    }
    this->Registers = this->Inputs + 1;
    for (std::size_t p = 0; p < this->Items.size(); ++p)
    {
      this->Released.clear();
      const Item& item = this->Items[p];
      if (item.Output >= 0)
      {
        this->EmitStore(item.Output, static_cast<int>(p));
      }
      else
      {
        this->EmitNode(item.Node, static_cast<int>(p));
      }
    }
    this->Tape.Registers = this->Registers;
  }

  /// Frees the register of `node` if item `position` reads it last.
  void Release(int node, int position)
  {
    if (node >= this->Inputs && this->LastUse[node] == position &&
      std::find(this->Released.begin(), this->Released.end(), node) == this->Released.end())
    {
      this->Released.push_back(node);
      this->FreeRegisters.push_back(this->Reg[node]);
    }
  }

  int AcquireRegister()
  {
    if (!this->FreeRegisters.empty())
    {
      const int r = this->FreeRegisters.back();
      this->FreeRegisters.pop_back();
      return r;
    }
    return this->Registers++;
  }

  void EmitStore(int output, int position)
  {
    Instruction in{};
    const Ref& r = this->Graph.Outputs[output];
    in.B = output;
    if (r.Id < 0)
    {
      in.Operation = Code::StoreConst;
      in.C = r.Scale;
    }
    else
    {
      in.Operation = r.Scale == 1.0 ? Code::Store : Code::StoreScaled;
      in.A = this->Reg[r.Id];
      in.C = r.Scale;
      this->Release(r.Id, position);
    }
    this->Tape.Instructions.push_back(in);
  }

  void EmitNode(int id, int position)
  {
    const OperandGroups& groups = this->Groups[id];
    // Groups padded to one width with register One.
    std::size_t width = 1;
    for (const std::vector<int>& g : groups)
    {
      width = std::max(width, g.size());
    }
    std::vector<int> args;
    for (const std::vector<int>& g : groups)
    {
      for (std::size_t f = 0; f < width; ++f)
      {
        args.push_back(f < g.size() ? this->Reg[g[f]] : this->One);
      }
    }
    // Operands are read before the result is written: the result may reuse
    // an operand's register.
    for (const std::vector<int>& g : groups)
    {
      for (int a : g)
      {
        this->Release(a, position);
      }
    }
    Instruction in{};
    in.D = this->Reg[id] = this->AcquireRegister();
    const Node& node = this->Graph.Nodes[id];
    if (node.Operation != Op::Const)
    {
      ++this->Tape.Operations;
    }
    this->Encode(node, width, args, in);
    this->Tape.Instructions.push_back(in);
  }

  /// The code and operands of `node`, whose operand registers are `args`.
  void Encode(const Node& node, std::size_t width, const std::vector<int>& args, Instruction& in)
  {
    switch (node.Operation)
    {
      case Op::Const:
        in.Operation = Code::Const;
        in.C = node.Constant;
        break;
      case Op::Lin:
        this->EncodeLin(node, width, args, in);
        break;
      case Op::Mul:
        this->EncodeMul(args, in);
        break;
      default:
        EncodeOneOrTwoArguments(node.Operation, args, in);
        break;
    }
  }

  /// A sum: AddC, Lin1, Add2 or Sub2 where they fit, else Lin, LinP2 or LinP3.
  void EncodeLin(const Node& node, std::size_t width, const std::vector<int>& args, Instruction& in)
  {
    in.C = node.Constant;
    if (width == 1 && args.size() == 1)
    {
      in.Operation = node.Coefficients[0] == 1.0 ? Code::AddC : Code::Lin1;
      in.A = args[0];
      in.K = node.Coefficients[0];
    }
    else if (width == 1 && args.size() == 2 && node.Constant == 0.0 &&
      node.Coefficients[0] == 1.0 && (node.Coefficients[1] == 1.0 || node.Coefficients[1] == -1.0))
    {
      in.Operation = node.Coefficients[1] == 1.0 ? Code::Add2 : Code::Sub2;
      in.A = args[0];
      in.B = args[1];
    }
    else
    {
      in.Operation = width == 1 ? Code::Lin : (width == 2 ? Code::LinP2 : Code::LinP3);
      in.N = static_cast<std::int32_t>(node.Args.size());
      in.A = static_cast<std::int32_t>(this->Tape.Operands.size());
      in.B = static_cast<std::int32_t>(this->Tape.Coefficients.size());
      this->Tape.Operands.insert(this->Tape.Operands.end(), args.begin(), args.end());
      this->Tape.Coefficients.insert(
        this->Tape.Coefficients.end(), node.Coefficients.begin(), node.Coefficients.end());
    }
  }

  void EncodeMul(const std::vector<int>& args, Instruction& in)
  {
    if (args.size() == 2)
    {
      in.Operation = Code::Mul2;
      in.A = args[0];
      in.B = args[1];
    }
    else
    {
      in.Operation = Code::Mul;
      in.N = static_cast<std::int32_t>(args.size());
      in.A = static_cast<std::int32_t>(this->Tape.Operands.size());
      this->Tape.Operands.insert(this->Tape.Operands.end(), args.begin(), args.end());
    }
  }

  static void EncodeOneOrTwoArguments(Op operation, const std::vector<int>& args, Instruction& in)
  {
    static const std::pair<Op, Code> simple[] = { { Op::Div, Code::Div },
      { Op::Square, Code::Square }, { Op::Recip, Code::Recip }, { Op::Sqrt, Code::Sqrt },
      { Op::Pow, Code::Pow }, { Op::Exp, Code::Exp }, { Op::Log, Code::Log },
      { Op::Sin, Code::Sin }, { Op::Cos, Code::Cos }, { Op::Tan, Code::Tan },
      { Op::Sinh, Code::Sinh }, { Op::Cosh, Code::Cosh }, { Op::Tanh, Code::Tanh },
      { Op::Atan, Code::Atan }, { Op::Atan2, Code::Atan2 }, { Op::Abs, Code::Abs },
      { Op::Sign, Code::Sign } };
    for (const auto& [op, code] : simple)
    {
      if (op == operation)
      {
        in.Operation = code;
      }
    }
    in.A = args.at(0);
    in.B = args.size() > 1 ? args[1] : 0;
  }
};
} // namespace

ExpressionTape BuildExpressionTape(const ExpressionGraph& graph, int order, int inputs)
{
  return TapeBuilder(graph, order, inputs).Build();
}

int CountOperands(const ExpressionTape& tape)
{
  // An operand is a register read (a padding One of a product term included).
  int operands = 0;
  for (const Instruction& in : tape.Instructions)
  {
    ForEachRead(in, tape, [&](int) { ++operands; });
  }
  return operands;
}
} // namespace expression
} // namespace riemann
