using System.Numerics;
using AcDream.Core.Physics;
using static AcDream.Core.Tests.TestData;

namespace AcDream.Core.Tests.Regression;

/// <summary>
/// Issue 29, defect 11, and issue 31: what <see cref="DoorState.Closing"/>, <see cref="MoverRegistry.GetDoorState"/> and
/// <see cref="MoverRegistry.GetPendingDoorState"/> say is what they do. A door told to close reads
/// <see cref="DoorState.Closing"/> until the commit that makes it solid, whether or not anything is in it;
/// <see cref="MoverRegistry.GetDoorState"/> answers the state last committed, the one moves meet, and
/// <see cref="MoverRegistry.GetPendingDoorState"/> the changes made since.
/// </summary>
[Trait("Mutation", "MoverRegistry")]
public class DoorStateDocTests
{
    private const uint Lb = 0x1010FFFFu;
    private const uint Cell = 0x1010001Au;
    private const uint Door = 9u;

    [Fact]
    public void GetDoorState_AnswersTheCommittedState_AndGetPendingDoorState_TheChangesNotYetCommitted()
    {
        var engine = new PhysicsEngine(Lb);
        engine.AddLandblock(Lb, FlatTerrain(0f, Lb), []);
        engine.Movers.Add(Door, MoverShape.Cylinder(0.5f, 2f), new Vector3(100f, 100f, 0f), Cell, Quaternion.Identity, MoverState.Door);
        engine.Movers.GetPendingDoorState(Door).Should().Be(DoorState.Closed);
        Action notCommitted = () => engine.Movers.GetDoorState(Door);
        notCommitted.Should().Throw<ArgumentException>("no commit has published the door yet").WithParameterName("doorId").WithMessage("*0x00000009*not yet committed*");
        engine.Movers.Commit();
        float Walk() => engine.Resolve(new Vector3(97f, 100f, 0f), Cell, new Vector3(6f, 0f, 0f), 0.5f, MovementOptions.Player).Position.X;
        const float Stopped = 100f - 0.5f - 0.48f; // the body's front at the door's side

        (engine.Movers.GetDoorState(Door), engine.Movers.GetPendingDoorState(Door)).Should().Be((DoorState.Closed, DoorState.Closed));
        Walk().Should().BeApproximately(Stopped, 1e-3f, "closed, it blocks");

        engine.Movers.Open(Door);
        engine.Movers.GetPendingDoorState(Door).Should().Be(DoorState.Open, "the change made, not yet committed");
        engine.Movers.GetDoorState(Door).Should().Be(DoorState.Closed, "committed: closed, as moves meet it");
        Walk().Should().BeApproximately(Stopped, 1e-3f, "moves meet the state last committed: still closed");
        engine.Movers.Commit();
        engine.Movers.GetDoorState(Door).Should().Be(DoorState.Open, "open from the commit on");
        Walk().Should().BeApproximately(103f, 1e-3f, "open from the commit on");

        engine.Movers.Close(Door); // nothing stands in it
        engine.Movers.GetPendingDoorState(Door).Should().Be(DoorState.Closing, "told to close, not yet solid: Closing until the next commit, with nothing in it");
        engine.Movers.GetDoorState(Door).Should().Be(DoorState.Open, "committed: still open");
        Walk().Should().BeApproximately(103f, 1e-3f, "still open as committed");
        engine.Movers.Commit();
        (engine.Movers.GetDoorState(Door), engine.Movers.GetPendingDoorState(Door)).Should().Be((DoorState.Closed, DoorState.Closed), "solid at the first commit with nothing in it");
        Walk().Should().BeApproximately(Stopped, 1e-3f, "closed again");
    }
}
