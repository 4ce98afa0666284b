using System.Numerics;
using AcDream.Core.Physics;

namespace AcDream.Core.Tests.Objects;

/// <summary>
/// A move across the seam between a landblock with outdoor objects and one without: the landblock
/// without objects has an empty object grid, and the move among objects must not index into it
/// (found by the host's Holtburg walk crossing 0xA8B4 → 0xA9B4 with the cottage's shell registered).
/// </summary>
public class SeamToLandblockWithoutObjectsTests
{
    private const uint WithObjects = 0xA9B4FFFF;
    private const uint Without = 0xA8B4FFFF;
    private const float Ground = 50f;

    private static PhysicsEngine Engine()
    {
        (var setup, var parts) = ObjectKit.Tree();
        var tree = new ObjectSurface(setup, parts, ObjectKit.At(new Vector3(96f, 96f, Ground), 0f), 0);
        var engine = new PhysicsEngine(WithObjects);
        engine.AddLandblock(WithObjects, TestData.FlatTerrain(Ground, WithObjects), [], [tree]);
        engine.AddLandblock(Without, TestData.FlatTerrain(Ground, Without), []);
        return engine;
    }

    [Theory]
    [InlineData(-0.05f, 0.1f)] // from the landblock without objects into the one with
    [InlineData(0.05f, -0.1f)] // and back
    public void Resolve_AcrossTheSeam_MovesWithoutTouchingTheEmptyGrid(float startX, float dx)
    {
        PhysicsEngine engine = Engine();
        var start = new Vector3(startX, 50f, Ground);

        foreach (MovementOptions options in new[] { MovementOptions.Literal, MovementOptions.Player })
        {
            ResolveResult r = engine.Resolve(start, 0u, new Vector3(dx, 0f, 0f), 0.6f, options);

            r.Position.X.Should().BeApproximately(startX + dx, 1e-4f, $"nothing stands in the way ({options})");
            r.Position.Z.Should().Be(Ground);
            r.IsOnGround.Should().BeTrue();
            engine.LandblockAt(r.Position).Should().Be(dx > 0 ? WithObjects : Without);
        }
    }
}
