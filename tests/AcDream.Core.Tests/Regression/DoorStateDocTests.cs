using System.Numerics;
using AcDream.Core.Physics;
using static AcDream.Core.Tests.TestData;

namespace AcDream.Core.Tests.Regression;

/// <summary>
/// Issue 29, defect 11: what <see cref="DoorState.Closing"/> and <see cref="Movers.GetDoorState"/> say is what they do. A door
/// told to close reads <see cref="DoorState.Closing"/> until the commit that makes it solid, whether or not anything is in
/// it; <see cref="Movers.GetDoorState"/> answers the changes made so far, while moves meet the state last committed.
/// </summary>
[Trait("Mutation", "MoverRegistry")]
public class DoorStateDocTests
{
    private const uint Lb = 0x1010FFFFu;
    private const uint Cell = 0x1010001Au;
    private const uint Door = 9u;

    [Fact]
    public void GetDoorState_AnswersTheChangesNotYetCommitted_ClosingUntilTheCommitThatMakesItSolid()
    {
        var engine = new PhysicsEngine(Lb);
        engine.AddLandblock(Lb, FlatTerrain(0f, Lb), []);
        engine.Movers.Add(Door, MoverShape.Cylinder(0.5f, 2f), new Vector3(100f, 100f, 0f), Cell, Quaternion.Identity, MoverState.Door);
        engine.Movers.Commit();
        float Walk() => engine.Resolve(new Vector3(97f, 100f, 0f), Cell, new Vector3(6f, 0f, 0f), 0.5f, MovementOptions.Player).Position.X;
        const float Stopped = 100f - 0.5f - 0.48f; // the body's front at the door's side

        engine.Movers.GetDoorState(Door).Should().Be(DoorState.Closed);
        Walk().Should().BeApproximately(Stopped, 1e-3f, "closed, it blocks");

        engine.Movers.Open(Door);
        engine.Movers.GetDoorState(Door).Should().Be(DoorState.Open, "the change made, not yet committed");
        Walk().Should().BeApproximately(Stopped, 1e-3f, "moves meet the state last committed: still closed");
        engine.Movers.Commit();
        Walk().Should().BeApproximately(103f, 1e-3f, "open from the commit on");

        engine.Movers.Close(Door); // nothing stands in it
        engine.Movers.GetDoorState(Door).Should().Be(DoorState.Closing, "told to close, not yet solid: Closing until the next commit, with nothing in it");
        Walk().Should().BeApproximately(103f, 1e-3f, "still open as committed");
        engine.Movers.Commit();
        engine.Movers.GetDoorState(Door).Should().Be(DoorState.Closed, "solid at the first commit with nothing in it");
        Walk().Should().BeApproximately(Stopped, 1e-3f, "closed again");
    }
}
