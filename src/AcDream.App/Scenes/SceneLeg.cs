using System.Numerics;

namespace AcDream.App.Scenes;

/// <summary>
/// One leg of a scene: either walk to a point (<see cref="To"/> set; the mover faces it each frame
/// and slows to land on it; reached when there on the ground), or hold an intent (forward, strafe, turn) for
/// <see cref="Seconds"/>; either may start with a jump, and open or close a door.
/// </summary>
/// <param name="Name">Shown in the summary.</param>
/// <param name="To">Target point, world metres; null for an intent leg.</param>
/// <param name="Forward">Intent leg: −1..1.</param>
/// <param name="Strafe">Intent leg: −1..1, + right.</param>
/// <param name="Turn">Intent leg: −1..1, + clockwise.</param>
/// <param name="Run">Run speed instead of walk speed.</param>
/// <param name="Backward">Point leg: walk there backwards, facing away from it.</param>
/// <param name="Seconds">Intent leg: its length; point leg: the time limit after which it stops unreached.</param>
/// <param name="Jump">Jump on the leg's first frame (when the effects move the body vertically and it is on the ground).</param>
/// <param name="JumpSkill">The jump skill for the leg (<see cref="Movement.PlayerMovementMode.JumpSkill"/>).</param>
/// <param name="Open">A door of the scene opened on the leg's first frame, before the move (<see cref="Core.Physics.MoverRegistry.Open"/>); null: none.</param>
/// <param name="Close">A door of the scene told to close on the leg's first frame (<see cref="Core.Physics.MoverRegistry.Close"/>: held open while a mover stands in it); null: none.</param>
internal sealed record SceneLeg(string Name, Vector2? To, float Forward, float Strafe, float Turn, bool Run, bool Backward, float Seconds, bool Jump = false, int JumpSkill = Movement.PlayerMovementMode.DefaultJumpSkill,
    string? Open = null, string? Close = null);
