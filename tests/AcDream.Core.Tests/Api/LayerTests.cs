using ArchUnitNET.Domain;
using ArchUnitNET.Fluent;
using ArchUnitNET.Loader;
using ArchUnitNET.xUnit;
using AcDream.Core.Physics;
using static ArchUnitNET.Fluent.ArchRuleDefinition;

namespace AcDream.Core.Tests.Api;

/// <summary>
/// The engine's layers, low to high: Surfaces → Movers → World → Point → Body → Casting → Drawing
/// (<c>docs/physics.md</c>, "Layers"). A layer is the namespace of its folder under
/// <c>src/AcDream.Core/Physics/</c>, and <see cref="MoverRegistry"/>, the public type whose state is the
/// Movers layer's. Each layer may depend only on the layers below it and on the root namespace's public
/// contract types (the surfaces, the options, the results, the constants); never on a layer above it, on
/// <see cref="PhysicsEngine"/> or <see cref="Character"/>, which sit on top and may use anything.
/// </summary>
public class LayerTests
{
    private const string Root = "AcDream.Core.Physics";

    /// <summary>The layers, low to high.</summary>
    public static readonly string[] Order = ["Surfaces", "Movers", "World", "Point", "Body", "Casting", "Drawing"];

    /// <summary>The public types of the root namespace that belong to a layer (their file is in its folder and they hold its state).</summary>
    private static readonly Dictionary<string, string> LayerOfPublic = new() { ["MoverRegistry"] = "Movers" };

    /// <summary>The public face: on top of every layer, may depend on anything, and no layer may depend on it.</summary>
    private static readonly HashSet<string> Face = ["PhysicsEngine", "Character"];

    private static readonly Architecture Engine =
        new ArchLoader().LoadAssemblies(typeof(PhysicsEngine).Assembly).Build();

    public static TheoryData<string> Layers() => new(Order);

    [Theory]
    [MemberData(nameof(Layers))]
    public void A_layer_depends_only_on_the_layers_below_it_and_the_public_contract(string layer)
    {
        int rank = Array.IndexOf(Order, layer);
        IArchRule rule = Types().That().FollowCustomPredicate(t => RankOf(t) == rank, $"are in the {layer} layer")
            .Should().NotDependOnAnyTypesThat().FollowCustomPredicate(
                t => IsForbiddenFor(rank, t),
                $"are in a layer above {layer}, are the engine's face (PhysicsEngine, Character) or are internal to the root namespace")
            .Because($"the layers are ordered {string.Join(" → ", Order)}");

        rule.Check(Engine);
    }

    [Fact]
    public void Every_layer_has_types_and_the_root_holds_only_public_types()
    {
        foreach (string layer in Order)
        {
            Engine.Types.Should().Contain(t => t.Namespace.FullName == $"{Root}.{layer}", $"the {layer} layer is a namespace");
        }

        Engine.Types.Where(t => t.Namespace.FullName == Root && IsTopLevel(t) && !IsCompilerMade(t))
            .Should().OnlyContain(t => t.Visibility == Visibility.Public, "the root namespace is the engine's public face");
    }

    /// <summary>The rank of a type's layer (0 = Surfaces), −1 for a root public contract type, int.MaxValue for the face; −2 outside the engine.</summary>
    private static int RankOf(IType type)
    {
        string ns = type.Namespace.FullName;
        if (ns.StartsWith(Root + ".", StringComparison.Ordinal))
        {
            return Array.IndexOf(Order, ns[(Root.Length + 1)..]);
        }

        if (ns != Root)
        {
            return -2;
        }

        string name = TopLevelName(type);
        if (Face.Contains(name))
        {
            return int.MaxValue;
        }

        return LayerOfPublic.TryGetValue(name, out string? layer) ? Array.IndexOf(Order, layer) : -1;
    }

    private static bool IsForbiddenFor(int rank, IType target)
    {
        int targetRank = RankOf(target);
        if (targetRank == -1)
        {
            // The root namespace's contract: allowed when public (a nested type counts as its outer type).
            return !IsCompilerMade(target) && Outermost(target).Visibility != Visibility.Public;
        }

        return targetRank > rank;
    }

    private static string TopLevelName(IType type)
    {
        string name = type.FullName[(type.Namespace.FullName.Length + 1)..];
        int cut = name.IndexOfAny(['+', '`', '/']);
        return cut < 0 ? name : name[..cut];
    }

    private static bool IsTopLevel(IType type) => TopLevelName(type) == type.FullName[(type.Namespace.FullName.Length + 1)..].Split('`')[0];

    private static bool IsCompilerMade(IType type) => type.FullName.Contains('<');

    private static IType Outermost(IType type)
    {
        string top = $"{type.Namespace.FullName}.{TopLevelName(type)}";
        return Engine.Types.FirstOrDefault(t => t.FullName == top) ?? type;
    }
}
