using AcDream.Core.Physics;

namespace AcDream.Core.Tests.Moving;

/// <summary>Movers for the tests: a creature of the game's human size (the slab and the distances are <see cref="AcDream.Testing.MoverReference"/>'s).</summary>
internal static class MoverKit
{
    public const float HumanRadius = 0.48f;
    public const float HumanHeight = 1.835f;

    public static MoverShape Human { get; } = MoverShape.Cylinder(HumanRadius, HumanHeight);
}
