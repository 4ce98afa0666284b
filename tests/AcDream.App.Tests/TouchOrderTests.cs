using System.Numerics;
using AcDream.App.Movement;
using AcDream.Core.Physics;
using static AcDream.App.Tests.TestWorlds;

namespace AcDream.App.Tests;

/// <summary>
/// Issue 29, defect 11: <see cref="PlayerMovementMode.Touched"/> is in the order first touched, as its docs say. Movers
/// one step passed were named in the order the committed state files them (their registration order), not along the path.
/// </summary>
public sealed class TouchOrderTests
{
    private const uint Cell = 0xA9B40025u;

    [Theory]
    [InlineData(new[] { 7, 6, 5, 4, 3, 2, 1, 0 })] // registered farthest first
    [InlineData(new[] { 3, 0, 6, 1, 7, 4, 2, 5 })]
    public void Update_OneStepThroughEightEtherealCreatures_NamesThemInTheOrderItReachesThem(int[] registration)
    {
        PhysicsEngine engine = Engine(Heights((_, _) => 50));
        var start = new Vector3(96f, 96f, 50f);
        engine.Movers.Add(1u, MoverShape.Cylinder(0.48f, 1.835f), start, Cell, Quaternion.Identity, MoverState.Player);
        var ghost = new MoverState(MoverKind.Creature, PhysicsStateFlags.Ethereal);
        foreach (int k in registration)
        {
            // Thin creatures 0.05 m apart, north of the body's front (0.48 m): creature k is reached k-th.
            engine.Movers.Add(100u + (uint)k, MoverShape.Cylinder(0.01f, 1.8f), start + new Vector3(0f, 0.5f + (0.05f * k), 0f), Cell, Quaternion.Identity, ghost);
        }

        engine.Movers.Commit();
        var mode = new PlayerMovementMode(engine, start, Cell, 0f, MovementOptions.Player) { MoverId = 1u };

        CharacterStep frame = mode.Update(new MovementIntent(1f, 0f, 0f, true), new CharacterSettings().MaxStepSeconds); // one step, 0.4 m north

        frame.Steps.Should().Be(1);
        mode.Position.Y.Should().BeApproximately(96.4f, 1e-4f, "Ethereal creatures do not stop it");
        mode.Touched.ToArray().Should().Equal([100u, 101u, 102u, 103u, 104u, 105u, 106u, 107u], "nearest first, as the body reaches them");
    }
}
